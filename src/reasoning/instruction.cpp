// Instruction interpretation (see instruction.hpp).

#include "ussnav/reasoning/instruction.hpp"

#include <algorithm>
#include <cctype>
#include <set>

#include "ussnav/core/error.hpp"
#include "ussnav/perception/wordnet.hpp"

namespace ussnav {
namespace {

const std::set<std::string>& fillers() {
  static const std::set<std::string> f{
      "a",     "an",    "the",  "to",   "i",      "me",   "my",       "want",     "wants",  "need",  "needs",
      "would", "like",  "find", "go",   "get",    "look", "looking",  "for",      "some",   "somewhere",
      "something", "place", "where", "can", "could", "please", "in",  "on",       "at",     "of",    "with",
      "and",   "or",    "is",   "are",  "be",     "there", "any",     "anywhere", "let",    "lets",  "us",
      "we",    "you",   "it",   "that", "which",  "near", "nearest",  "closest",  "show",   "take", "bring",
      "search", "locate", "fly", "navigate", "this", "these", "those", "one", "from", "into", "by", "up",
      "do",    "does",  "have", "has",  "am",     "where's", "whats", "what", "your", "our", "their", "his",
      "her",   "its",   "go", "head", "towards", "toward", "object", "thing", "area", "spot", "room", "use", "using"};
  return f;
}

// Words after which a verb stands: "to print", "I wash", "can eat", "please watch", "let's eat".
const std::set<std::string>& verbCues() {
  static const std::set<std::string> c{"to",   "i",     "we",    "you",  "can",  "could", "please", "lets", "let's",
                                       "i'd",  "i'll",  "we'd",  "must", "will", "shall", "should", "let"};
  return c;
}

// Verbs that take their meaning from the act after them: "take a bath", "have a nap".
const std::set<std::string>& lightVerbs() {
  static const std::set<std::string> v{"take", "have", "get", "grab", "taking", "having"};
  return v;
}

bool physicalLexfile(const std::string& lf) {
  return lf == "noun.artifact" || lf == "noun.plant" || lf == "noun.object" || lf == "noun.food";
}

std::string joinWords(const std::vector<std::string>& w, size_t a, size_t b) {
  std::string s;
  for (size_t i = a; i < b; ++i) s += (i > a ? " " : "") + w[i];
  return s;
}

// Exact room-type name or alias (no fuzzy match: "bed" must not become "bedroom").
int exactRoom(const CommonsensePriors& P, const std::string& phrase) {
  for (size_t i = 0; i < P.rooms().size(); ++i) {
    const RoomType& r = P.rooms()[i];
    if (r.name == phrase) return int(i);
    for (const auto& a : r.aliases)
      if (a == phrase) return int(i);
  }
  return -1;
}

std::set<std::string> stems(const std::string& text) {
  std::set<std::string> out;
  for (const auto& w : instructionWords(text))
    if (!fillers().count(w)) out.insert(stemWord(w));
  return out;
}

// Step 3's score of one name against the request's stemmed content words `want` (of them
// `verbs` stand as verbs): 2 per word in the name or its synonyms, 1.5 per purpose ("a place TO
// SLEEP", "used FOR COOKING"), 1 per other mention, in the name's WordNet gloss, its nearest
// hypernym's gloss (a chair is "a seat", a seat "furniture that is designed for sitting on") and
// `extra_text`; an -ing word of the name adds its verb's gloss as purposes ("dining" table: to
// dine is to "eat dinner"). A verb of the request counts in a gloss only where the gloss uses it
// as a verb: a purpose, an -ing / -ed form, after "can" ("where several people can SIT"); a book
// is "a written work", not somewhere to work. `object` false (room types, scored on our own
// descriptions, written as purposes): no hypernym, no verb glosses.
double requestScore(const std::set<std::string>& want, const std::set<std::string>& verbs, const std::string& name,
                    const std::string& extra_text, bool object) {
  std::string synonyms;
  for (const auto& syn : wordnet::synonymsOf(name)) synonyms += syn + " ";
  const std::set<std::string> name_words = stems(name + " " + synonyms);
  std::string gloss = wordnet::glossOf(name) + " " + extra_text;
  if (object)
    if (const auto h = wordnet::hypernymsOf(name); !h.empty()) gloss += " ; " + wordnet::glossOf(h.front());
  const std::set<std::string> gloss_words = stems(gloss), extra_words = stems(extra_text);
  std::set<std::string> purposes, verb_forms;
  // A name with an -ing word says what the thing is for: a dining table is for dining, and to
  // dine is to "have supper; eat dinner".
  if (object)
    for (const auto& w : instructionWords(name))
      if (w.size() > 5 && w.ends_with("ing"))
        for (const auto& p : stems(wordnet::verbGlossOf(w))) purposes.insert(p);
  const auto g = instructionWords(gloss);
  for (size_t i = 0; i < g.size(); ++i) {
    if (i + 1 < g.size() && (g[i] == "to" || g[i] == "for")) purposes.insert(stemWord(g[i + 1]));
    const auto ends = [&](const char* x) { return g[i].size() > 4 && g[i].ends_with(x); };
    if (ends("ing") || ends("ed")) verb_forms.insert(stemWord(g[i]));
    if (i + 1 < g.size() && (g[i] == "can" || g[i] == "could" || g[i] == "may" || g[i] == "will"))
      verb_forms.insert(stemWord(g[i + 1]));  // "where several people can SIT"
  }
  double s = 0.0;
  for (const auto& w : want)
    s += name_words.count(w) ? 2.0
         : purposes.count(w) ? 1.5
         : extra_words.count(w) || (gloss_words.count(w) && (!verbs.count(w) || verb_forms.count(w))) ? 1.0
                              : 0.0;
  // A compound known only by its head noun ("dog bed" -> bed) ranks after the head itself.
  if (const auto r = wordnet::resolveLabel(name); r && !r->modifiers.empty()) s *= 0.9;
  return s;
}

}  // namespace

std::vector<std::string> instructionWords(const std::string& text) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : text) {
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '\'') {
      cur += char(std::tolower(static_cast<unsigned char>(c)));
    } else if (!cur.empty()) {
      out.push_back(cur);
      cur.clear();
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

std::string stemWord(const std::string& w) {
  auto ends = [&](const std::string& s) { return w.size() > s.size() + 2 && w.compare(w.size() - s.size(), s.size(), s) == 0; };
  std::string s = w;
  if (ends("ing")) s = w.substr(0, w.size() - 3);
  else if (ends("ed")) s = w.substr(0, w.size() - 2);
  else if (ends("es") && !ends("ses")) s = w.substr(0, w.size() - 1);
  else if (ends("s") && !ends("ss")) s = w.substr(0, w.size() - 1);
  // A doubled final consonant left by the suffix goes: "sitting" and "sit", "stopped" and "stop"
  // ("dressing", "falling" and "buzzing" keep theirs).
  if (s != w && s.size() > 3 && s.back() == s[s.size() - 2] && std::string("aeioulsz").find(s.back()) == std::string::npos)
    s.pop_back();
  // A final silent e goes on both sides: "store" and "stored", "bake" and "baking" meet.
  if (s.size() > 3 && s.back() == 'e' && s[s.size() - 2] != 'e') s.pop_back();
  return s;
}

Instruction interpretInstruction(const std::string& text, const CommonsensePriors& P,
                                 const std::vector<std::string>& extra_vocabulary) {
  Instruction I;
  I.text = text;
  std::vector<std::string> words = instructionWords(text);
  if (words.empty()) throw InputError("goal", "", "empty instruction; expected an object or a request, e.g. \"bed\"");

  // 1. Room constraint: the longest n-gram naming a room type; its words leave the sentence.
  for (size_t n = 3; n >= 1 && I.room.empty(); --n)
    for (size_t i = 0; i + n <= words.size(); ++i) {
      const int r = exactRoom(P, joinWords(words, i, i + n));
      if (r < 0) continue;
      I.room = P.rooms()[size_t(r)].name;
      words.erase(words.begin() + long(i), words.begin() + long(i + n));
      break;
    }
  // Content words, and which of them stand as verbs: a word WordNet knows as a verb after "to",
  // "I", "can", ... ("somewhere to wash", "where can I store food"), or first and followed by
  // another content word ("watch tv"). WordNet also has a print, a watch, a wash and a store
  // among its artifacts; a verb names what to do, not what to look for.
  std::vector<std::string> content;
  std::vector<bool> verb;
  for (size_t i = 0; i < words.size(); ++i) {
    if (fillers().count(words[i])) continue;
    const bool cued = i > 0 && verbCues().count(words[i - 1]);
    const bool leads = i == 0 &&
                       std::any_of(words.begin() + 1, words.end(), [](const std::string& x) { return !fillers().count(x); });
    content.push_back(words[i]);
    verb.push_back((cued || leads) && wordnet::knownAsVerb(words[i]));
  }
  if (content.empty()) {
    if (!I.room.empty()) {
      I.how = "room_only";
      return I;
    }
    throw InputError("goal", "", "'" + text + "' names nothing to look for; expected an object or a request");
  }

  // 2. A named object: the longest n-gram of content words that is a physical thing; one with a
  // verb in it only when WordNet knows the whole n-gram ("washing machine", "dining table").
  const TextEncoder& enc = P.encoder();
  std::string named;
  for (size_t n = std::min<size_t>(3, content.size()); n >= 1 && named.empty(); --n)
    for (size_t i = 0; i + n <= content.size(); ++i) {
      const std::string phrase = joinWords(content, i, i + n);
      const bool has_verb = std::any_of(verb.begin() + long(i), verb.begin() + long(i + n), [](bool v) { return v; });
      if (has_verb && (n < 2 || !wordnet::lookupNoun(phrase))) continue;
      const auto sense = wordnet::lookupNoun(phrase);
      bool is_named = sense && physicalLexfile(sense->lexfile);
      if (!is_named)
        for (const auto& c : P.categories())
          if (enc.similarity(phrase, c) >= 0.9) {
            is_named = true;
            break;
          }
      if (is_named) {
        named = phrase;
        std::fill(verb.begin() + long(i), verb.begin() + long(i + n), false);  // "washing" machine
        break;
      }
    }
  // A light verb and an act ("take a bath", "have a nap") ask for what the act needs, when the
  // noun names no category itself: the act's WordNet gloss ("you soak and wash your body in a
  // bathtub") becomes the request (a bath's artifact sense is a laboratory vessel).
  std::vector<std::string> act;
  if (!named.empty() && named.find(' ') == std::string::npos) {
    const auto at = std::find(words.begin(), words.end(), named);
    size_t k = size_t(at - words.begin());
    while (k > 0 && (words[k - 1] == "a" || words[k - 1] == "an" || words[k - 1] == "the")) --k;
    const bool after_light_verb = at != words.end() && k > 0 && lightVerbs().count(words[k - 1]);
    const auto names_category = [&] {
      return std::any_of(P.categories().begin(), P.categories().end(),
                         [&](const std::string& c) { return enc.similarity(named, c) >= 0.85; });
    };
    if (after_light_verb && !names_category()) act = instructionWords(wordnet::actGlossOf(named));
  }
  if (!act.empty()) {
    named.clear();
    content.clear();
    verb.clear();
    for (const auto& w : act)
      if (!fillers().count(w)) content.push_back(w), verb.push_back(false);
  }
  const bool any_verb = std::find(verb.begin(), verb.end(), true) != verb.end();
  if (!named.empty() && !any_verb) {
    I.targets.push_back(named);
    I.how = "named";
    return I;
  }

  // 3. A functional request: content words against names, synonyms and glosses.
  std::set<std::string> want, verbs;
  for (size_t i = 0; i < content.size(); ++i) {
    want.insert(stemWord(content[i]));
    if (verb[i]) verbs.insert(stemWord(content[i]));
  }
  I.request.assign(want.begin(), want.end());
  I.request_verbs.assign(verbs.begin(), verbs.end());
  const auto score = [&](const std::string& name, const std::string& extra_text, bool object = true) {
    return requestScore(want, verbs, name, extra_text, object);
  };
  std::vector<std::string> vocab = P.categories();
  for (const auto& v : extra_vocabulary)
    if (std::find(vocab.begin(), vocab.end(), v) == vocab.end()) vocab.push_back(v);
  std::vector<std::pair<double, std::string>> scored;
  for (const auto& v : vocab)
    if (const double s = score(v, ""); s > 0.0) scored.push_back({s, v});
  // Best first; among equals the shorter name ("shower" before "shower curtain").
  const auto words_in = [](const std::string& x) { return std::count(x.begin(), x.end(), ' '); };
  std::stable_sort(scored.begin(), scored.end(), [&](const auto& a, const auto& b) {
    return a.first != b.first ? a.first > b.first : words_in(a.second) < words_in(b.second);
  });
  double best_room = 0.0;
  for (const RoomType& r : P.rooms()) {
    std::string aliases;
    for (const auto& a : r.aliases) aliases += a + " ";
    const double s = score(r.name, r.description + " " + aliases, false);
    if (s > best_room) best_room = s, I.room_hint = r.name;
  }
  // With a verb, the object named stays the target unless a category answers the verb and the
  // object together better than the object's own name ("wash clothes" -> washing machine, "a
  // home appliance for washing clothes"; "read a book" -> book; "watch tv" -> tv).
  if (!named.empty() && (scored.empty() || scored.front().first <= score(named, ""))) {
    I.targets.push_back(named);
    I.how = "named";
    return I;
  }
  for (const auto& [s, v] : scored) {
    if (s < scored.front().first || I.targets.size() >= 3) break;
    I.targets.push_back(v);
  }
  if (!I.targets.empty()) {
    I.how = "functional";
    I.score = scored.front().first;
    return I;
  }
  if (!I.room_hint.empty() && I.room.empty()) {
    I.room = I.room_hint;
    I.how = "room_only";
    return I;
  }
  // 4. Literal: the content words as a label.
  I.targets.push_back(joinWords(content, 0, content.size()));
  I.how = "literal";
  return I;
}

double requestScore(const Instruction& I, const std::string& label) {
  if (I.how != "functional") return 0.0;
  const std::set<std::string> want(I.request.begin(), I.request.end()), verbs(I.request_verbs.begin(), I.request_verbs.end());
  return requestScore(want, verbs, label, "", true);
}

bool servesRequest(const Instruction& I, const std::string& label) {
  if (I.how != "functional" || I.score <= 0.0) return false;
  // A compound known by its head noun scores 0.9 of the head ("office chair"), as in ranking,
  // and serves where its head does, unless a word before the head names an animal: a dog bed is
  // no place for a person to sleep (as for "find a bed", docs/reasoning.md). (Letting a label
  // inherit what its hypernyms serve, an armchair being a chair, also let a plunger, a "hand
  // tool", serve "somewhere to wash my hands".)
  double need = I.score;
  if (const auto r = wordnet::resolveLabel(label); r && !r->modifiers.empty() &&
                                                   std::none_of(r->modifiers.begin(), r->modifiers.end(), wordnet::namesAnimal))
    need *= 0.9;
  return requestScore(I, label) >= need - 1e-9;
}

}  // namespace ussnav
