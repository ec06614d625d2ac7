// Step 3's score of a name against a request (see request_match.hpp).

#include "request_match.hpp"

#include <algorithm>
#include <map>
#include <mutex>
#include <tuple>
#include <vector>

#include "request_words.hpp"
#include "ussnav/perception/wordnet.hpp"
#include "ussnav/reasoning/instruction.hpp"

namespace ussnav::request {
namespace {

// What a name's words, synonyms and glosses say, whatever the request: read once per name and
// kept for the process (a request is scored against every category, and objects seen are judged
// again and again; WordNet's data does not change while it runs).
struct NameFacts {
  std::vector<std::string> tokens;  // the name's words
  std::set<std::string> name_words, gloss_words, extra_words;
  std::set<std::string> purposes, verb_forms, acts;  // acts: the gloss's verbs as written
  std::set<std::string> ing_purposes;                 // an -ing word's verb gloss: acts, or mentions
  std::set<std::string> purpose_acts;                 // the purposes as written ("to SLEEP")
  bool head_only = false;                             // known by its head noun ("dog bed")
};

NameFacts readName(const std::string& name, const std::string& extra_text, const std::string& kind_gloss, bool object,
                   bool hypernym) {
  NameFacts f;
  f.tokens = instructionWords(name);
  std::string synonyms;
  for (const auto& syn : wordnet::synonymsOf(name)) synonyms += syn + " ";
  f.name_words = stems(name + " " + synonyms);
  if (object)
    for (const auto& w : f.tokens)
      for (const auto& part : compoundParts(w)) f.name_words.insert(stemWord(part));
  std::string gloss = wordnet::glossOf(name) + " " + extra_text;
  if (!kind_gloss.empty()) gloss += " ; " + kind_gloss;
  if (object && hypernym)
    if (const auto h = wordnet::hypernymsOf(name); !h.empty()) gloss += " ; " + wordnet::glossOf(h.front());
  f.gloss_words = stems(gloss);
  f.extra_words = stems(extra_text);
  // A name with an -ing word says what the thing is for: a dining table is for dining, and to
  // dine is to "have supper; eat dinner". Its verbs answer the request's acts as purposes, its
  // other words only as mentions: the verb's first sense may be another's (to shelve is first
  // "to hold back to a later time", no shelving unit to check the time with).
  if (object)
    for (const auto& w : f.tokens)
      if (w.size() > 5 && w.ends_with("ing"))
        for (const auto& p : stems(wordnet::verbGlossOf(w))) f.ing_purposes.insert(p);
  const auto g = instructionWords(gloss);
  for (size_t i = 0; i < g.size(); ++i) {
    // "a pot for stewing OR BOILING": the purposes joined by "or" / "and" too.
    if (i + 1 < g.size() && (g[i] == "to" || g[i] == "for"))
      for (size_t k = i + 1; k < g.size(); k += 2) {
        f.purposes.insert(stemWord(g[k])), f.acts.insert(g[k]), f.purpose_acts.insert(g[k]);
        if (k + 2 >= g.size() || (g[k + 1] != "or" && g[k + 1] != "and")) break;
      }
    const auto ends = [&](const char* x) { return g[i].size() > 4 && g[i].ends_with(x); };
    if (ends("ing") || ends("ed")) f.verb_forms.insert(stemWord(g[i])), f.acts.insert(g[i]);
    if (i + 1 < g.size() && (g[i] == "can" || g[i] == "could" || g[i] == "may" || g[i] == "will"))
      f.verb_forms.insert(stemWord(g[i + 1])), f.acts.insert(g[i + 1]);  // "where several people can SIT"
  }
  const auto r = wordnet::resolveLabel(name);
  f.head_only = r && !r->modifiers.empty();
  return f;
}

const NameFacts& nameFacts(const std::string& name, const std::string& extra_text, const std::string& kind_gloss,
                           bool object, bool hypernym) {
  static std::mutex mutex;
  static std::map<std::tuple<std::string, std::string, std::string, bool, bool>, NameFacts> cache;
  auto key = std::make_tuple(name, extra_text, kind_gloss, object, hypernym);
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (const auto it = cache.find(key); it != cache.end()) return it->second;
  }
  NameFacts f = readName(name, extra_text, kind_gloss, object, hypernym);
  std::lock_guard<std::mutex> lock(mutex);
  // std::map never moves its elements: a reference handed out stays good while others are added.
  return cache.emplace(std::move(key), std::move(f)).first->second;
}

RequestMatch matchRequestIn(const std::set<std::string>& want, const std::set<std::string>& verbs,
                            const std::string& name, const std::string& extra_text, const std::string& kind_gloss,
                            bool object, bool hypernym) {
  const NameFacts& f = nameFacts(name, extra_text, kind_gloss, object, hypernym);
  const auto& [tokens, name_words, gloss_words, extra_words, purposes, verb_forms, acts, ing_purposes, purpose_acts,
               head_only] = f;
  const auto purpose = [&](const std::string& w) {
    return purposes.count(w) > 0 || (verbs.count(w) > 0 && ing_purposes.count(w) > 0);
  };
  // The act in other words, as what the thing is for: to nap is to sleep, and a bed is "a place
  // to SLEEP"; to sleep is to rest, and to rest is to lie (WordNet's verb hypernyms, three steps
  // up), so a bed serves "somewhere to rest" and "I want to lie down" too.
  // So does a noun of the act as a purpose: a toilet is "for defecation and URINATION", and
  // urination is what to pee is.
  const auto purpose_kin = [&](const std::string& w) {
    if (!object || !verbs.count(w)) return false;
    for (const auto& k : kinVerbStems(verbOfStem(w)))
      if (purposes.count(k) || ing_purposes.count(k)) return true;
    for (const auto& n : wordnet::verbKin(verbOfStem(w)).nouns)  // after "to" / "for" only
      if (n.find(' ') == std::string::npos && stemWord(n) != w &&
          std::any_of(purpose_acts.begin(), purpose_acts.end(), [&](const std::string& p) { return stemWord(p) == stemWord(n); }))
        return true;
    for (const auto& p : purpose_acts)
      for (const auto& a : wordnet::verbAncestors(p, 3))
        if (a.find(' ') == std::string::npos && !generalVerb(a) && stemWord(a) == w) return true;
    return false;
  };
  const auto kin = [&](const std::string& w) {
    if (!object || !verbs.count(w)) return false;
    const std::string verb = verbOfStem(w);
    for (const auto& k : kinVerbStems(verb))
      if (verb_forms.count(k)) return true;
    for (const auto& n : wordnet::verbKin(verb).nouns)  // not the verb's own noun: a book is "a written work"
      if (n.find(' ') == std::string::npos && stemWord(n) != w && gloss_words.count(stemWord(n))) return true;
    for (const auto& a : acts)
      if (!generalVerb(a) && kinVerbStems(a).count(w)) return true;
    return false;
  };
  RequestMatch m;
  int kin_verbs = 0, purpose_kin_verbs = 0;
  // A verb of the request that is the name's own word serves only when WordNet makes the thing
  // from the act: a shower is to shower, an iron to iron; a watch (the timepiece) is not to watch.
  const auto homograph = [&](const std::string& w) {
    return object && verbs.count(w) && tokens.size() == 1 && stemWord(name) == w &&
           !wordnet::nounOfVerb(name, verbOfStem(w));
  };
  // A thing WordNet derives from the act names it: a printer is to print, a toaster to toast.
  // So does a word of a compound name: a vacuum CLEANER is to clean.
  const auto agent = [&](const std::string& w) {
    if (!object || !verbs.count(w)) return false;
    if (tokens.size() == 1) return stemWord(name) != w && wordnet::nounOfVerb(name, verbOfStem(w));
    return std::any_of(tokens.begin(), tokens.end(), [&](const std::string& x) {
      return stemWord(x) != w && wordnet::nounOfVerb(x, verbOfStem(w));
    });
  };
  for (const auto& w : want) {
    // A verb too general to name an act ("make" coffee) counts only in a name: a switch is "for
    // making or breaking a connection", no place to make coffee.
    const bool general = verbs.count(w) && generalVerb(verbOfStem(w));
    const double s = (name_words.count(w) && !homograph(w)) || agent(w) ? 2.0
                     : general                                          ? 0.0
                     : purpose(w)                                       ? 1.5
                     : extra_words.count(w) || ing_purposes.count(w) || (gloss_words.count(w) && (!verbs.count(w) || verb_forms.count(w))) ? 1.0
                                                                                                               : 0.0;
    m.score += s;
    if (s > 0.0) (verbs.count(w) ? m.verb : m.object) = true;
    if (s > 0.0 && s < 2.0 && verbs.count(w)) m.purpose = true;
    if (s == 2.0 && verbs.count(w)) m.act_named = true;
    if (s > 0.0 && s < 2.0 && verbs.count(w)) m.for_act = true;
    if (s == 0.0 && !general && purpose_kin(w)) ++purpose_kin_verbs;
    else if (s == 0.0 && !general && kin(w)) ++kin_verbs;
  }
  if (purpose_kin_verbs > 0) m.score += purpose_kin_verbs, m.verb = m.purpose = true;
  // The act in other words counts only beside what it is on: a bottle "can be capped", and to
  // cap is to "lie at the top of", but it is no place to lie down.
  if (m.object && kin_verbs > 0) m.score += kin_verbs, m.verb = m.purpose = true;
  if (object && m.verb && m.object) m.score += 0.5;
  // A compound known only by its head noun ("dog bed" -> bed) ranks after the head itself.
  if (head_only) m.score *= 0.9;
  return m;
}

}  // namespace

// What the thing's own name and gloss answer counts in full, what only its hypernym's gloss
// answers 0.9: a dining table (to dine is to "eat dinner") before a butter knife (a table
// knife is "used for eating") for "I'm hungry".
// What only a kind of it is for counts 0.8: a sink may be a washbasin, "where you can wash your
// hands and face", a pot a teapot, "for brewing tea". Only where the kind's gloss says the act
// itself, as a verb: a conference table is "usually in a conference room for meetings", and a
// horse cart "used for farm work" (to farm is to work), but neither table nor cart answers "I
// want to attend a meeting" or "somewhere to work".
RequestMatch matchRequest(const std::set<std::string>& want, const std::set<std::string>& verbs,
                          const std::string& name, const std::string& extra_text, bool object, bool kinds) {
  RequestMatch full = matchRequestIn(want, verbs, name, extra_text, "", object, object);
  if (!object) return full;
  const double own = matchRequestIn(want, verbs, name, extra_text, "", object, false).score;
  full.score = own + 0.9 * (full.score - own);
  if (!kinds) return full;
  for (const auto& gloss : wordnet::kindGlossesOf(name)) {
    RequestMatch kind = matchRequestIn(want, verbs, name, extra_text, gloss, object, false);
    kind.score *= 0.8;
    if (kind.for_act && kind.score > full.score + 1e-9) full = kind;
  }
  return full;
}

}  // namespace ussnav::request
