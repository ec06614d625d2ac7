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
      "her",   "its",   "go", "head", "towards", "toward", "object", "thing", "area", "spot", "room"};
  return f;
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
  if (ends("ing")) return w.substr(0, w.size() - 3);
  if (ends("ed")) return w.substr(0, w.size() - 2);
  if (ends("es") && !ends("ses")) return w.substr(0, w.size() - 1);
  if (ends("s") && !ends("ss")) return w.substr(0, w.size() - 1);
  return w;
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
  std::vector<std::string> content;
  for (const auto& w : words)
    if (!fillers().count(w)) content.push_back(w);
  if (content.empty()) {
    if (!I.room.empty()) {
      I.how = "room_only";
      return I;
    }
    throw InputError("goal", "", "'" + text + "' names nothing to look for; expected an object or a request");
  }

  // 2. A named object: the longest n-gram of content words that is a physical thing.
  const TextEncoder& enc = P.encoder();
  for (size_t n = std::min<size_t>(3, content.size()); n >= 1 && I.targets.empty(); --n)
    for (size_t i = 0; i + n <= content.size(); ++i) {
      const std::string phrase = joinWords(content, i, i + n);
      const auto sense = wordnet::lookupNoun(phrase);
      bool named = sense && physicalLexfile(sense->lexfile);
      if (!named)
        for (const auto& c : P.categories())
          if (enc.similarity(phrase, c) >= 0.9) {
            named = true;
            break;
          }
      if (named) {
        I.targets.push_back(phrase);
        I.how = "named";
        break;
      }
    }
  if (!I.targets.empty()) return I;

  // 3. A functional request: content words against names, synonyms and glosses.
  std::set<std::string> want;
  for (const auto& w : content) want.insert(stemWord(w));
  auto score = [&](const std::string& name, const std::string& extra_text) {
    const std::set<std::string> name_words = stems(name + " " + [&] {
      std::string s;
      for (const auto& syn : wordnet::synonymsOf(name)) s += syn + " ";
      return s;
    }());
    const std::string gloss = wordnet::glossOf(name) + " " + extra_text;
    const std::set<std::string> gloss_words = stems(gloss);
    // A purpose ("a place TO SLEEP", "used FOR SLEEPING") says more than a mention.
    std::set<std::string> purposes;
    const auto g = instructionWords(gloss);
    for (size_t i = 0; i + 1 < g.size(); ++i)
      if (g[i] == "to" || g[i] == "for") purposes.insert(stemWord(g[i + 1]));
    double s = 0.0;
    for (const auto& w : want)
      s += name_words.count(w) ? 2.0 : gloss_words.count(w) ? (purposes.count(w) ? 1.5 : 1.0) : 0.0;
    // A compound known only by its head noun ("dog bed" -> bed) ranks after the head itself.
    if (const auto r = wordnet::resolveLabel(name); r && !r->modifiers.empty()) s *= 0.9;
    return s;
  };
  std::vector<std::string> vocab = P.categories();
  for (const auto& v : extra_vocabulary)
    if (std::find(vocab.begin(), vocab.end(), v) == vocab.end()) vocab.push_back(v);
  std::vector<std::pair<double, std::string>> scored;
  for (const auto& v : vocab)
    if (const double s = score(v, ""); s > 0.0) scored.push_back({s, v});
  std::stable_sort(scored.begin(), scored.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  double best_room = 0.0;
  for (const RoomType& r : P.rooms()) {
    std::string aliases;
    for (const auto& a : r.aliases) aliases += a + " ";
    const double s = score(r.name, r.description + " " + aliases);
    if (s > best_room) best_room = s, I.room_hint = r.name;
  }
  for (const auto& [s, v] : scored) {
    if (s < scored.front().first || I.targets.size() >= 3) break;
    I.targets.push_back(v);
  }
  if (!I.targets.empty()) {
    I.how = "functional";
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

}  // namespace ussnav
