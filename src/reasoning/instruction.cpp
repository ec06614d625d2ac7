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

// A part of the body ("hands", "teeth", "face") is the requester's own, not a thing to look for
// in the building, though WordNet also has a clock's hands and a saw's teeth among its artifacts.
bool bodyPart(const std::string& phrase) { return wordnet::usualNounLexfile(phrase) == "noun.body"; }

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

struct RequestMatch {
  double score = 0.0;
  bool verb = false;    // a verb of the request found (the act)
  bool object = false;  // a word of the request that is no verb found (what the act is on)
  bool purpose = false;  // a verb found in what the gloss says the thing is for, not in its name
};

// Step 3's score of one name against the request's stemmed content words `want` (of them
// `verbs` stand as verbs): 2 per word in the name, its synonyms or a closed compound's parts
// (book-shelf), 1.5 per purpose ("a place TO SLEEP", "used FOR COOKING"), 1 per other mention,
// in the name's WordNet gloss, its nearest hypernym's gloss (a chair is "a seat", a seat
// "furniture that is designed for sitting on") and `extra_text`; an -ing word of the name adds
// its verb's gloss as purposes ("dining" table: to dine is to "eat dinner"). A verb of the
// request counts in a gloss only where the gloss uses it as a verb: a purpose, an -ing / -ed
// form, after "can" ("where several people can SIT"); a book is "a written work", not somewhere
// to work. Failing those, 1 where the gloss names the act in other words (wordnet::verbKin: a
// dresser is "for KEEPING clothes" and to store is to keep; a refrigerator is where food "can be
// STORED" for "keep food cold"; a wardrobe "provides STORAGE"). A name that answers both the act
// and what it is on gets 0.5 more ("store clothes": a dresser, not a clothes dryer).
// `object` false (room types, scored on our own descriptions, written as purposes): no
// hypernym, no verb glosses, no kin.
RequestMatch matchRequest(const std::set<std::string>& want, const std::set<std::string>& verbs,
                          const std::string& name, const std::string& extra_text, bool object) {
  std::string synonyms;
  for (const auto& syn : wordnet::synonymsOf(name)) synonyms += syn + " ";
  std::set<std::string> name_words = stems(name + " " + synonyms);
  if (object)
    for (const auto& w : instructionWords(name))
      for (const auto& part : compoundParts(w)) name_words.insert(stemWord(part));
  std::string gloss = wordnet::glossOf(name) + " " + extra_text;
  if (object)
    if (const auto h = wordnet::hypernymsOf(name); !h.empty()) gloss += " ; " + wordnet::glossOf(h.front());
  const std::set<std::string> gloss_words = stems(gloss), extra_words = stems(extra_text);
  std::set<std::string> purposes, verb_forms, acts;  // acts: the gloss's verbs as written
  // A name with an -ing word says what the thing is for: a dining table is for dining, and to
  // dine is to "have supper; eat dinner".
  if (object)
    for (const auto& w : instructionWords(name))
      if (w.size() > 5 && w.ends_with("ing"))
        for (const auto& p : stems(wordnet::verbGlossOf(w))) purposes.insert(p);
  const auto g = instructionWords(gloss);
  for (size_t i = 0; i < g.size(); ++i) {
    if (i + 1 < g.size() && (g[i] == "to" || g[i] == "for")) purposes.insert(stemWord(g[i + 1])), acts.insert(g[i + 1]);
    const auto ends = [&](const char* x) { return g[i].size() > 4 && g[i].ends_with(x); };
    if (ends("ing") || ends("ed")) verb_forms.insert(stemWord(g[i])), acts.insert(g[i]);
    if (i + 1 < g.size() && (g[i] == "can" || g[i] == "could" || g[i] == "may" || g[i] == "will"))
      verb_forms.insert(stemWord(g[i + 1])), acts.insert(g[i + 1]);  // "where several people can SIT"
  }
  const auto kin = [&](const std::string& w) {
    if (!object || !verbs.count(w)) return false;
    const std::string verb = verbOfStem(w);
    for (const auto& k : kinVerbStems(verb))
      if (purposes.count(k) || verb_forms.count(k)) return true;
    for (const auto& n : wordnet::verbKin(verb).nouns)  // not the verb's own noun: a book is "a written work"
      if (n.find(' ') == std::string::npos && stemWord(n) != w && gloss_words.count(stemWord(n))) return true;
    for (const auto& a : acts)
      if (!generalVerb(a) && kinVerbStems(a).count(w)) return true;
    return false;
  };
  RequestMatch m;
  int kin_verbs = 0;
  // A verb of the request that is the name's own word serves only when WordNet makes the thing
  // from the act: a shower is to shower, an iron to iron; a watch (the timepiece) is not to watch.
  const auto homograph = [&](const std::string& w) {
    return object && verbs.count(w) && instructionWords(name).size() == 1 && stemWord(name) == w &&
           !wordnet::nounOfVerb(name, verbOfStem(w));
  };
  for (const auto& w : want) {
    const double s = name_words.count(w) && !homograph(w) ? 2.0
                     : purposes.count(w) ? 1.5
                     : extra_words.count(w) || (gloss_words.count(w) && (!verbs.count(w) || verb_forms.count(w))) ? 1.0
                                                                                                               : 0.0;
    m.score += s;
    if (s > 0.0) (verbs.count(w) ? m.verb : m.object) = true;
    if (s > 0.0 && s < 2.0 && verbs.count(w)) m.purpose = true;
    if (s == 0.0 && kin(w)) ++kin_verbs;
  }
  // The act in other words counts only beside what it is on: a bottle "can be capped", and to
  // cap is to "lie at the top of", but it is no place to lie down.
  if (m.object && kin_verbs > 0) m.score += kin_verbs, m.verb = m.purpose = true;
  if (object && m.verb && m.object) m.score += 0.5;
  // A compound known only by its head noun ("dog bed" -> bed) ranks after the head itself.
  if (const auto r = wordnet::resolveLabel(name); r && !r->modifiers.empty()) m.score *= 0.9;
  return m;
}

double requestScore(const std::set<std::string>& want, const std::set<std::string>& verbs, const std::string& name,
                    const std::string& extra_text, bool object) {
  return matchRequest(want, verbs, name, extra_text, object).score;
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
  // "Clothes" is no plural of "cloth" (that is "cloths"): clothes and clothing meet, a cloth
  // (a shower curtain is a "hanging cloth") stays apart.
  if (w == "clothes" || w == "clothing" || w == "clothe") return "clothes";
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
      bool is_named = sense && physicalLexfile(sense->lexfile) && !bodyPart(phrase);
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
  // A request that names what the act is on ("store CLOTHES", "watch TV") is answered only by
  // things that name it too: a watch is no place to watch tv, nor a dresser ("for keeping
  // clothes") one to keep shoes. Without any such thing, anything answering the act is kept.
  std::vector<RequestMatch> matches;
  matches.reserve(vocab.size());
  for (const auto& v : vocab) matches.push_back(matchRequest(want, verbs, v, "", true));
  // An act on the requester's body names what it is on too: "wash my HANDS" asks for no
  // washing machine.
  const bool names_object = !named.empty() || std::any_of(content.begin(), content.end(), bodyPart);
  I.object_named = names_object && std::any_of(matches.begin(), matches.end(), [](const RequestMatch& m) { return m.object; });
  std::vector<std::pair<double, std::string>> scored;
  for (size_t i = 0; i < vocab.size(); ++i)
    if (matches[i].score > 0.0 && (!I.object_named || matches[i].object)) scored.push_back({matches[i].score, vocab[i]});
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
  // home appliance for washing clothes"; "read a book" -> book; "watch tv" -> tv). Asked for a
  // place ("somewhere to hang my coat", "where can I store clothes"), the object named is what
  // the act is on and only one candidate: the request is judged, so a coat rack, a wardrobe or
  // a bookshelf seen serves it though the priors' vocabulary has none.
  const bool place = std::any_of(words.begin(), words.end(), [](const std::string& w) {
    return w == "somewhere" || w == "anywhere" || w == "place" || w == "where" || w == "spot";
  });
  if (!named.empty() && place) {
    if (std::none_of(scored.begin(), scored.end(), [&](const auto& x) { return stems(x.second) == stems(named); })) {
      const double own = score(named, "");
      const auto at = std::find_if(scored.begin(), scored.end(), [&](const auto& x) { return x.first <= own; });
      scored.insert(at, {own, named});
    }
  } else if (!named.empty() && (scored.empty() || scored.front().first <= score(named, ""))) {
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

namespace {
RequestMatch matchRequest(const Instruction& I, const std::string& label) {
  const std::set<std::string> want(I.request.begin(), I.request.end()), verbs(I.request_verbs.begin(), I.request_verbs.end());
  return matchRequest(want, verbs, label, "", true);
}
}  // namespace

double requestScore(const Instruction& I, const std::string& label) {
  return I.how == "functional" ? matchRequest(I, label).score : 0.0;
}

bool servesRequest(const Instruction& I, const std::string& label) {
  if (I.how != "functional" || I.score <= 0.0) return false;
  // A compound known by its head noun scores 0.9 of the head ("office chair"), as in ranking,
  // and serves where its head does, unless a word before the head names an animal: a dog bed is
  // no place for a person to sleep (as for "find a bed", docs/reasoning.md).
  double need = I.score;
  if (const auto r = wordnet::resolveLabel(label); r && !r->modifiers.empty() &&
                                                   std::none_of(r->modifiers.begin(), r->modifiers.end(), wordnet::namesAnimal))
    need *= 0.9;
  const RequestMatch m = matchRequest(I, label);
  if (I.object_named && !m.object) return false;
  if (m.score >= need - 1e-9) return true;
  // A kind of a thing that serves the act serves it too: an armchair is a chair, and a chair
  // serves "somewhere to sit" (a seat is "designed for sitting on"). Only through what its gloss
  // says it is for: a plunger is a "hand tool", which names the hands but serves no "wash my
  // hands".
  // And only for a request its targets answer as a purpose (1.5) at least: a mention of "work"
  // three glosses up does not make a pen serve "work out".
  const auto h = wordnet::hypernymsOf(label);
  if (h.empty() || I.score < 1.5) return false;
  const RequestMatch up = matchRequest(I, h.front());
  return up.purpose && (!I.object_named || up.object) && up.score >= I.score - 1e-9;
}

}  // namespace ussnav
