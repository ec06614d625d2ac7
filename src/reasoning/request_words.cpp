// The words of a request (see request_words.hpp).

#include "request_words.hpp"

#include "ussnav/perception/wordnet.hpp"
#include "ussnav/reasoning/instruction.hpp"

namespace ussnav::request {

const std::set<std::string>& fillers() {
  static const std::set<std::string> f{
      "a",     "an",    "the",  "to",   "i",      "me",   "my",       "want",     "wants",  "need",  "needs",
      "would", "like",  "find", "go",   "get",    "look", "looking",  "for",      "some",   "somewhere",
      "something", "place", "where", "can", "could", "please", "in",  "on",       "at",     "of",    "with",
      "and",   "or",    "is",   "are",  "be",     "there", "any",     "anywhere", "let",    "lets",  "us",
      "we",    "you",   "it",   "that", "which",  "near", "nearest",  "closest",  "show",   "take", "bring",
      "search", "locate", "fly", "navigate", "this", "these", "those", "one", "from", "into", "by", "up",
      "do",    "does",  "have", "has",  "am",     "where's", "whats", "what", "your", "our", "their", "his",
      "her",   "its",   "go", "head", "towards", "toward", "object", "thing", "area", "spot", "room", "use", "using",
      "i'm", "im", "i've", "i'd", "i'll", "we'd", "we're", "it's", "going", "gonna", "wanna", "feel", "feeling", "very", "really", "so", "bit", "little"};
  return f;
}

// Words after which a verb stands: "to print", "I wash", "can eat", "please watch", "let's eat".
const std::set<std::string>& verbCues() {
  static const std::set<std::string> c{"to",   "i",     "we",    "you",  "can",  "could", "please", "lets", "let's",
                                       "i'd",  "i'll",  "we'd",  "must", "will", "shall", "should", "let"};
  return c;
}

// Words of degree between a state and who is in it: "I'm SO tired", "I'm A BIT cold", "be VERY hot".
const std::set<std::string>& degreeWords() {
  static const std::set<std::string> d{"so",       "very",    "really", "too",    "quite",  "pretty",
                                       "rather",   "a",       "bit",    "little", "all",    "kind",
                                       "sort",     "of",      "kinda",  "super",  "totally", "completely",
                                       "terribly", "awfully", "extremely", "incredibly", "just", "still"};
  return d;
}

// Verbs that take their meaning from the act after them: "take a bath", "have a nap".
const std::set<std::string>& lightVerbs() {
  static const std::set<std::string> v{"take", "have", "get", "grab", "taking", "having"};
  return v;
}

std::set<std::string> stems(const std::string& text) {
  std::set<std::string> out;
  for (const auto& w : instructionWords(text))
    if (!fillers().count(w)) out.insert(stemWord(w));
  return out;
}

// A closed compound's parts, when both are WordNet nouns of four letters or more: a bookshelf
// is named for books and a coatrack for coats ("carpet" and "cupboard" stay whole).
std::vector<std::string> compoundParts(const std::string& word) {
  for (size_t k = 4; k + 4 <= word.size(); ++k) {
    const std::string head = word.substr(0, k), tail = word.substr(k);
    if (wordnet::lookupNoun(head) && wordnet::lookupNoun(tail))
      return {head, tail};
  }
  return {};
}

// Verbs too general to stand for another act: "eat" is to "take in", "relax" to "turn".
bool generalVerb(const std::string& w) {
  static const std::set<std::string> g{"make", "move", "change", "put", "set", "cause", "act",
                                       "hold", "give", "be",   "turn", "become"};
  return g.count(w) || g.count(stemWord(w)) || fillers().count(w) || lightVerbs().count(w);
}

// The verb a stem stands for: the request keeps stems ("stor" for "store", "sit" for "sitting").
std::string verbOfStem(const std::string& stem) {
  return wordnet::knownAsVerb(stem) || !wordnet::knownAsVerb(stem + "e") ? stem : stem + "e";
}

// Stems of the single-word verbs that name a verb's act (wordnet::verbKin), general ones dropped.
std::set<std::string> kinVerbStems(const std::string& verb) {
  std::set<std::string> out;
  for (const auto& v : wordnet::verbKin(verb).verbs)
    if (v.find(' ') == std::string::npos && !generalVerb(v)) out.insert(stemWord(v));
  return out;
}

}  // namespace ussnav::request
