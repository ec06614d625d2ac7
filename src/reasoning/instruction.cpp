// Instruction interpretation (see instruction.hpp).

#include "ussnav/reasoning/instruction.hpp"

#include <algorithm>
#include <cctype>
#include <functional>
#include <map>
#include <set>

#include "request_match.hpp"
#include "request_words.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/perception/wordnet.hpp"

namespace ussnav {
namespace {

using namespace request;

bool physicalLexfile(const std::string& lf) {
  return lf == "noun.artifact" || lf == "noun.plant" || lf == "noun.object" || lf == "noun.food";
}

// A part of the body ("hands", "teeth", "face") is the requester's own, not a thing to look for
// in the building, though WordNet also has a clock's hands and a saw's teeth among its artifacts.
bool bodyPart(const std::string& phrase) { return wordnet::usualNounLexfile(phrase) == "noun.body"; }

// A thing called by the act's own word is a candidate only when that is what the word first
// means: a mop is "a cleaning implement", to mop is to clean with one; a print is first a
// printed text, a work an activity, a heat a form of energy.
bool sameWordTool(const std::string& noun) {
  return wordnet::usualNounLexfile(noun) == "noun.artifact" && !noun.ends_with("ing");
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

// Whether the request asks for a place: "somewhere to hang my coat", "where can I eat".
bool place_asked(const std::vector<std::string>& words) {
  return std::any_of(words.begin(), words.end(), [](const std::string& w) {
    return w == "somewhere" || w == "anywhere" || w == "place" || w == "where" || w == "spot";
  });
}

// Whether a phrase names a category of the priors (text cosine 0.85 or more).
bool namesCategory(const CommonsensePriors& P, const std::string& phrase) {
  return std::any_of(P.categories().begin(), P.categories().end(),
                     [&](const std::string& c) { return P.encoder().similarity(phrase, c) >= 0.85; });
}

// How the one asking feels, rewritten as what they ask for (states.tsv): "I'm so tired" ->
// "I'm to sleep". Only a word that says how someone or something is, with the words of degree
// between ("a bit", "so"): after "I'm", "I feel", ..., or after "is", "are", "getting", ... whose
// subject is a person or an animal ("we are", "I am getting", "my son is") or a thing someone
// has or names ("my hands are", "the dishes are"). A thing in a state whose row has an act is what the act is
// done to: "my hands are dirty" -> "to wash my hands", "the soup is getting cold" -> "to warm the
// soup"; without one, a thing of someone's stands for them ("my feet are tired" -> "to sleep").
// "keep food cold", "a cold drink" and "a drink that is cold" stay.
void rewriteStates(std::vector<std::string>& words, const CommonsensePriors& P) {
  static const std::set<std::string> person_cues{"i'm", "im", "am", "feel", "feels", "feeling", "felt",
                                                 "i've", "we're", "you're", "they're", "he's", "she's"};
  static const std::set<std::string> copulas{"is", "are", "was", "were", "been", "get",
                                             "gets", "getting", "got", "become", "becoming"};
  static const std::set<std::string> persons{"i", "we", "you", "he", "she", "they"};
  static const std::set<std::string> possessives{"my", "our", "your", "his", "her", "their"};
  const std::set<std::string>& degree = degreeWords();
  // Whose state follows words[k]: a person's, a thing's (words[from] its determiner, the noun
  // next), or nobody's. A copula's subject is the word before it, words of degree aside, or the
  // subject of the copula before ("I am still getting", "my coffee is getting").
  struct Whose {
    enum { nobody, person, thing } kind = nobody;
    size_t from = 0;
  };
  const std::function<Whose(size_t)> whose = [&](size_t k) -> Whose {
    if (person_cues.count(words[k])) return {Whose::person};
    if (!copulas.count(words[k])) return {};
    size_t s = k;
    while (s > 0 && degree.count(words[s - 1])) --s;
    if (s == 0) return {};
    const std::string& subject = words[s - 1];
    if (persons.count(subject) || person_cues.count(subject)) return {Whose::person};
    if (copulas.count(subject)) return whose(s - 1);
    if (s < 2 || !(possessives.count(words[s - 2]) || words[s - 2] == "the")) return {};
    // A person or an animal is in the state as the one asking would be ("my dog is dirty": a bath).
    if (const std::string lf = wordnet::usualNounLexfile(subject); lf == "noun.person" || lf == "noun.animal")
      return {Whose::person};
    return {Whose::thing, s - 2};
  };
  std::vector<std::string> out;
  for (size_t i = 0; i < words.size(); ++i) {
    size_t c = i;
    while (c > 0 && degree.count(words[c - 1]) && whose(c - 1).kind == Whose::nobody) --c;
    // A word of degree is no state ("I'm still tired"), so each of them before one stands in out.
    const Whose w = c > 0 && !degree.count(words[i]) ? whose(c - 1) : Whose{};
    const CommonsensePriors::StateRow* row = w.kind == Whose::nobody ? nullptr : P.stateFor(words[i]);
    if (row && w.kind == Whose::thing && !row->act.empty()) {
      // The words from the determiner on were copied one for one (none of them is a state).
      out.resize(out.size() - (i - w.from));
      for (const std::string& x : {std::string("to"), row->act, words[w.from], words[w.from + 1]}) out.push_back(x);
      continue;
    }
    const bool someones = w.kind == Whose::person || (w.kind == Whose::thing && possessives.count(words[w.from]));
    if (!row || !someones) {
      out.push_back(words[i]);
      continue;
    }
    out.resize(out.size() - (i - c));  // "so", "a bit": they said how much, and go with the state
    for (auto& x : instructionWords(row->request)) out.push_back(std::move(x));
  }
  words = std::move(out);
}

// Rewrites what the later steps could not read, in place:
//  - a particle after a verb WordNet knows with it ("lie down", "heat up", "throw away", and after
//    a light verb: "take out the trash") goes and
//    the verb stays; when verb and particle closed up are a WordNet act ("work out" -> workout,
//    "exercise"), the act's first other one-word name, as a verb, stands for both;
//  - a word WordNet knows only as an adjective, whose definition says what it makes one want to
//    do, becomes that act: "hungry" ("a need or desire TO EAT food") -> "to eat", "thirsty" ->
//    "to drink".
void rewritePhrasesAndStates(std::vector<std::string>& words) {
  static const std::set<std::string> particles{"down", "up", "out", "away", "off", "on", "over"};
  std::vector<std::string> out;
  for (size_t i = 0; i < words.size(); ++i) {
    const std::string& w = words[i];
    // The verb: the word before the particle, or before the fillers before it ("throw this away").
    size_t v = i;
    while (v > 0 && fillers().count(words[v - 1]) && !verbCues().count(words[v - 1]) &&
           !lightVerbs().count(words[v - 1]))
      --v;
    // A light verb counts as the verb here ("take out the trash"): "out" is no act of its own.
    const bool verb_before = v > 0 && (!fillers().count(words[v - 1]) || lightVerbs().count(words[v - 1]));
    if (particles.count(w) && verb_before && wordnet::knownAsVerb(words[v - 1]) &&
        !wordnet::phrasalVerb(words[v - 1], w).empty()) {
      const std::string closed = words[v - 1] + w;  // "workout": an act, when WordNet has it
      if (const auto act = wordnet::lookupNoun(closed); v == i && act && act->lexfile == "noun.act")
        for (const auto& l : act->lemmas)
          if (l != closed && l.find(' ') == std::string::npos && wordnet::knownAsVerb(l)) {
            out.back() = "to";
            out.push_back(l);
            break;
          }
      continue;
    }
    if (!fillers().count(w) && !(i > 0 && verbCues().count(words[i - 1])) && !wordnet::lookupNoun(w)) {
      std::string act;
      for (const auto& gloss : wordnet::adjectiveGlossesOf(w, 2)) {
        const auto g = instructionWords(gloss);
        for (size_t k = 0; k + 1 < g.size() && act.empty(); ++k)
          if (g[k] == "to" && wordnet::knownAsVerb(g[k + 1]) && !generalVerb(g[k + 1])) act = g[k + 1];
        if (!act.empty()) break;
      }
      if (!act.empty()) {
        out.push_back("to");
        out.push_back(act);
        continue;
      }
    }
    out.push_back(w);
  }
  words = std::move(out);
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
  rewriteStates(words, P);
  rewritePhrasesAndStates(words);
  // Content words, and which of them stand as verbs: a word WordNet knows as a verb after "to",
  // "I", "can", ... ("somewhere to wash", "where can I store food"), or first and followed by
  // another content word ("watch tv"). WordNet also has a print, a watch, a wash and a store
  // among its artifacts; a verb names what to do, not what to look for.
  std::vector<std::string> content;
  std::vector<bool> verb;
  std::vector<size_t> at;  // where each content word stands in words
  for (size_t i = 0; i < words.size(); ++i) {
    if (fillers().count(words[i])) continue;
    const bool cued = i > 0 && verbCues().count(words[i - 1]);
    const bool leads = i == 0 &&
                       std::any_of(words.begin() + 1, words.end(), [](const std::string& x) { return !fillers().count(x); });
    content.push_back(words[i]);
    verb.push_back((cued || leads) && wordnet::knownAsVerb(words[i]));
    at.push_back(i);
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
      // Words said together: "water the plants" names no water plant.
      if (at[i + n - 1] - at[i] != n - 1) continue;
      const std::string phrase = joinWords(content, i, i + n);
      const bool has_verb = std::any_of(verb.begin() + long(i), verb.begin() + long(i + n), [](bool v) { return v; });
      if (has_verb && (n < 2 || !wordnet::lookupNoun(phrase))) continue;
      const auto sense = wordnet::lookupNoun(phrase);
      // A word whose thing is a rare sense of it names none: a rest is mostly a remainder or a
      // repose (a support is its sixth sense), water a substance, a document a writing; a tv is
      // a broadcast first and a receiver next. A category's name is matched below.
      bool is_named = sense && physicalLexfile(sense->lexfile) && !bodyPart(phrase) &&
                      (wordnet::pickedSenseRank(phrase) <= 1 || physicalLexfile(wordnet::usualNounLexfile(phrase)));
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
  // A light verb and an act ("take a bath", "have a nap"), or wanting one ("I need a nap", "I
  // want a drink"), ask for what the act needs, when the noun names no category itself: the act's
  // WordNet gloss ("you soak and wash your body in a bathtub") becomes the request (a bath's
  // artifact sense is a laboratory vessel).
  // The noun need not be a thing ("take a nap": a nap is mostly a sleep).
  static const std::set<std::string> wantVerbs{"need", "needs", "want", "wants", "use"};
  std::vector<std::string> act;
  for (size_t i = 0; i + 1 < words.size() && act.empty(); ++i) {
    if (!lightVerbs().count(words[i]) && !wantVerbs.count(words[i])) continue;
    size_t k = i + 1;
    while (k + 1 < words.size() && (words[k] == "a" || words[k] == "an" || words[k] == "the")) ++k;
    const std::string& noun = words[k];
    if (fillers().count(noun) || (!named.empty() && named != noun) || namesCategory(P, noun)) continue;
    act = instructionWords(wordnet::actGlossOf(noun));
    // A light verb and a meal or a drink that is a verb too: to have breakfast is to
    // breakfast, to "eat an early morning meal" (to take the trash is not to trash it).
    if (act.empty() && lightVerbs().count(words[i]) && wordnet::usualNounLexfile(noun) == "noun.food" &&
        wordnet::knownAsVerb(noun))
      act = instructionWords(wordnet::verbGlossOf(noun));
  }
  if (!act.empty()) {
    named.clear();
    content.clear();
    verb.clear();
    at.clear();  // read above only
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
    return matchRequest(want, verbs, name, extra_text, object).score;
  };
  std::vector<std::string> vocab = P.categories();
  for (const auto& v : extra_vocabulary)
    if (std::find(vocab.begin(), vocab.end(), v) == vocab.end()) vocab.push_back(v);
  // A WordNet compound of what the act is on and the act's own noun or its doer is the thing
  // for it: "wash the dishes" -> dishwasher, "brush my teeth" -> toothbrush, "make coffee" ->
  // coffee maker, "heat water" -> water heater. It names both, so it sets no bar for what else
  // serves (below): a coat rack still serves "somewhere to hang my coat" beside a coat hanger.
  std::set<std::string> compounds;
  for (size_t i = 0; i < content.size(); ++i) {
    if (verb[i]) continue;
    std::vector<long> added;  // senses already in: "dishwasher" and "dish washer" are one
    for (const auto& on : wordnet::nounForms(content[i]))
    for (const auto& v : verbs) {
      if (on.find(' ') != std::string::npos) continue;
      const std::string base = verbOfStem(v);
      std::vector<std::string> doers{base, base + "er", base + "r"};
      for (const auto& n : wordnet::verbKin(base).nouns) doers.push_back(n);
      for (const auto& d : doers) {
        if (d.find(' ') != std::string::npos) continue;  // the compound's being in WordNet is the test
        for (const std::string& c : {on + d, on + " " + d}) {
          const auto sense = wordnet::lookupNoun(c);
          const auto& l = sense ? sense->lemmas : std::vector<std::string>{};
          if (sense && sense->lexfile == "noun.artifact" && std::find(l.begin(), l.end(), c) != l.end() &&
              std::find(added.begin(), added.end(), sense->offset) == added.end() &&
              std::find(vocab.begin(), vocab.end(), c) == vocab.end() && !namesCategory(P, c)) {
            vocab.push_back(c);
            compounds.insert(c);
            added.push_back(sense->offset);
          }
        }
      }
    }
  }
  // What WordNet derives from the act as a thing is a candidate too, in the vocabulary or not:
  // "print a document" -> printer, "dry my hair" -> drier (a washer, read as a seal, is not).
  const size_t known_vocab = vocab.size();  // those after it are derived from the act
  for (const auto& v : verbs)
    for (const auto& n : wordnet::verbKin(verbOfStem(v)).nouns) {
      if (n.find(' ') != std::string::npos || (stemWord(n) == v && !sameWordTool(n)) ||
          std::find(vocab.begin(), vocab.end(), n) != vocab.end())
        continue;
      const auto sense = wordnet::lookupNoun(n);
      if (sense && sense->lexfile == "noun.artifact" && !wordnet::namesPlace(n) && wordnet::nounOfVerb(n, verbOfStem(v)))
        vocab.push_back(n);  // a brewery is no thing to brew tea with
    }
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
  // What the act is on is no category ("cook DINNER", "boil WATER"): the things answering the
  // act are what to look for, whether or not they name the object (a pan is for cooking, dinner
  // or not); the object named only when there are none.
  bool act_verb = false;  // a verb naming an act ("cook", not "make")
  for (size_t i = 0; i < content.size(); ++i) act_verb = act_verb || (verb[i] && !generalVerb(content[i]));
  const bool named_category = !named.empty() && namesCategory(P, named);
  // Unless the thing named is itself what the act is done with: a piano "is played by depressing
  // keys", so "play the piano" asks for a piano, not for a tennis racket (its gloss read last,
  // only when the rest holds).
  bool act_on_other = !named.empty() && act_verb && !place_asked(words) && !named_category &&
                      !matchRequest(want, verbs, named, "", true, false).for_act;
  std::vector<std::pair<double, std::string>> scored;
  std::set<std::string> act_named;
  bool known_scored = false;
  const auto collect = [&](bool acting_only) {
    for (size_t i = 0; i < vocab.size(); ++i) {
      const RequestMatch& m = matches[i];
      const bool keep = acting_only ? m.score > 0.0 && m.verb : m.score > 0.0 && (!I.object_named || m.object);
      if (!keep) continue;
      scored.push_back({m.score, vocab[i]});
      if (m.act_named) act_named.insert(vocab[i]);
      known_scored = known_scored || (i < known_vocab && m.score >= 1.5);
    }
  };
  collect(act_on_other);
  // Nothing answers the act ("POUR a glass of wine"): what names the object (a wine bottle).
  if (act_on_other && scored.empty()) act_on_other = false, collect(false);
  // A thing derived from the act is looked for only when no category of the vocabulary answers
  // the request by name or purpose ("boil water": a kettle, "a pot for stewing or boiling", not
  // a boiler; "print a document": a printer, though a book is "printed on pages"); seen, it
  // still serves (servesRequest).
  if (known_scored)
    std::erase_if(scored, [&](const auto& x) {
      return std::find(vocab.begin(), vocab.begin() + long(known_vocab), x.second) == vocab.begin() + long(known_vocab);
    });
  // Best first; among equals one named for the act ("wash my clothes": a WASHING machine before
  // a CLOTHES dryer, "a dryer that dries clothes wetted by washing"), then what a room is
  // furnished with ("where can I eat": a dining table before a fork; it stays where the act is
  // done and is seen from across the room), then the shorter name ("shower" before "shower
  // curtain").
  const auto words_in = [](const std::string& x) { return std::count(x.begin(), x.end(), ' '); };
  std::map<std::string, bool> furnishing;
  for (const auto& [s, v] : scored) furnishing.emplace(v, wordnet::furnishes(v));
  std::stable_sort(scored.begin(), scored.end(), [&](const auto& a, const auto& b) {
    if (a.first != b.first) return a.first > b.first;
    if (act_named.count(a.second) != act_named.count(b.second)) return act_named.count(a.second) > act_named.count(b.second);
    if (furnishing.at(a.second) != furnishing.at(b.second)) return furnishing.at(a.second);
    return words_in(a.second) < words_in(b.second);
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
  if (!named.empty() && place_asked(words)) {
    if (std::none_of(scored.begin(), scored.end(), [&](const auto& x) { return stems(x.second) == stems(named); })) {
      const double own = score(named, "");
      const auto at = std::find_if(scored.begin(), scored.end(), [&](const auto& x) { return x.first <= own; });
      scored.insert(at, {own, named});
    }
  } else if (act_on_other) {
    // scored holds what answers the act
  } else if (!named.empty() && (scored.empty() || scored.front().first <= score(named, ""))) {
    I.targets.push_back(named);
    I.how = "named";
    return I;
  }
  // A thing the act is on that could be an object in view stays a target after them: "watch
  // tv" looks for a tv monitor ("for monitoring the program", and to monitor is to watch) and a
  // tv; "clean the floor" for a vacuum cleaner and the floor.
  const auto named_sense = named.empty() ? std::nullopt : wordnet::lookupNoun(named);
  const bool keep_named = (act_on_other || place_asked(words)) && named_sense && named_sense->lexfile == "noun.artifact" &&
                          !named_category;
  for (const auto& [s, v] : scored) {
    if (s < scored.front().first || I.targets.size() >= (keep_named ? 2u : 3u)) break;
    I.targets.push_back(v);
  }
  if (keep_named && !I.targets.empty() && std::find(I.targets.begin(), I.targets.end(), named) == I.targets.end())
    I.targets.push_back(named);
  // An act on the requester's body is answered only by what does the act: a hair dryer is
  // "hand-held", but washes no hands.
  I.act_required = act_on_other || (act_verb && std::any_of(content.begin(), content.end(), bodyPart));
  if (act_on_other) I.object_named = false;  // answered by the act, whatever it is on
  if (!I.targets.empty()) {
    I.how = "functional";
    I.score = scored.front().first;
    for (const auto& [s, v] : scored)
      if (!compounds.count(v)) {
        I.score = std::min(I.score, s);  // the best score of the rest
        break;
      }
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
RequestMatch matchInstruction(const Instruction& I, const std::string& label, bool kinds = true) {
  const std::set<std::string> want(I.request.begin(), I.request.end()), verbs(I.request_verbs.begin(), I.request_verbs.end());
  return request::matchRequest(want, verbs, label, "", true, kinds);
}
}  // namespace

double requestScore(const Instruction& I, const std::string& label) {
  return I.how == "functional" ? matchInstruction(I, label).score : 0.0;
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
  // Judged by what the label itself is, not by what a kind of it may be: a can may be a canister,
  // "for storing dry foods", but a can seen is no place to store food (the targets were ranked
  // with the kinds; a target seen matches by name).
  const RequestMatch m = matchInstruction(I, label, false);
  if (I.object_named && !m.object) return false;
  if (I.act_required && !m.verb) return false;  // a floor lamp cleans no floor
  if (m.score >= need - 1e-9) return true;
  // A kind of a thing that serves the act serves it too: an armchair is a chair, and a chair
  // serves "somewhere to sit" (a seat is "designed for sitting on"). Only through what its gloss
  // says it is for: a plunger is a "hand tool", which names the hands but serves no "wash my
  // hands".
  // And only for a request its targets answer as a purpose (1.5, or 0.9 x 1.5 through their
  // hypernym, as a chair is a seat) at least: a mention of "work"
  // three glosses up does not make a pen serve "work out".
  const auto h = wordnet::hypernymsOf(label);
  if (h.empty() || I.score < 0.9 * 1.5 - 1e-9) return false;  // 0.9: a purpose its hypernym names
  // The hypernym's own gloss, not its kinds: those are the label's siblings (a microwave is a
  // kitchen appliance, and a kitchen appliance may be a refrigerator; a microwave keeps no food
  // cold).
  const RequestMatch up = matchInstruction(I, h.front(), false);
  return up.purpose && (!I.object_named || up.object) && up.score >= I.score - 1e-9;
}

}  // namespace ussnav
