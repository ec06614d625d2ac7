#include "ussnav/perception/wordnet.hpp"

#include <spdlog/spdlog.h>
#include <wn.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <functional>
#include <mutex>
#include <unordered_map>
#include <unordered_set>

namespace ussnav::wordnet {

namespace {

// The library prints errors through this hook; route them to the debug log instead of stderr.
int quietMessage(char* msg) {
  spdlog::debug("wordnet: {}", msg ? msg : "");
  return -1;
}

struct SynsetData {
  std::vector<std::string> words;
  std::string gloss;
  int fnum = 0;
  std::vector<long> hypernyms;
};

// All library access and every cache live behind one mutex (the C library uses globals).
class Db {
 public:
  static Db& get() {
    static Db db;
    return db;
  }

  std::mutex mutex;

  bool openLocked() {
    if (tried_) return open_;
    tried_ = true;
    if (dir_.empty()) {
      const char* env = std::getenv("WNSEARCHDIR");
      dir_ = (env && *env) ? std::filesystem::path(env) : std::filesystem::path("/usr/share/wordnet");
    }
    display_message = quietMessage;
    std::error_code ec;
    // wninit() reads WNSEARCHDIR; check the one file we need first for a clearer warning.
    if (!std::filesystem::exists(dir_ / "index.noun", ec) || !std::filesystem::exists(dir_ / "data.noun", ec)) {
      open_ = false;
    } else {
      ::setenv("WNSEARCHDIR", dir_.c_str(), 1);
      open_ = (initialised_ ? re_wninit() : wninit()) == 0;
      initialised_ = initialised_ || open_;
    }
    if (!open_)
      spdlog::warn("WordNet 3.0 not found in {} (install wordnet-base or set WNSEARCHDIR); "
                   "text embeddings fall back to character n-grams, glosses are empty",
                   dir_.string());
    else
      resolveAnchorsLocked();
    return open_;
  }

  bool reopenLocked(const std::filesystem::path& dir) {
    tried_ = false;
    dir_ = dir;
    synsets_.clear();
    depth_.clear();
    ancestors_.clear();
    nouns_.clear();
    kin.clear();
    noun_of_verb.clear();
    verb_ancestors.clear();
    return openLocked();
  }

  const std::filesystem::path& dir() const { return dir_; }

  const SynsetData& synset(long off) {
    auto it = synsets_.find(off);
    if (it != synsets_.end()) return it->second;
    SynsetData d;
    char empty[1] = {0};
    SynsetPtr s = read_synset(NOUN, off, empty);
    if (s) {
      for (int i = 0; i < s->wcount; ++i) d.words.emplace_back(s->words[i]);
      d.gloss = s->defn ? s->defn : "";
      d.fnum = s->fnum;
      for (int i = 0; i < s->ptrcount; ++i)
        if ((s->ptrtyp[i] == HYPERPTR || s->ptrtyp[i] == INSTANCE) && s->ppos[i] == NOUN)
          d.hypernyms.push_back(s->ptroff[i]);
      free_synset(s);
    }
    return synsets_.emplace(off, std::move(d)).first->second;
  }

  // Shortest hypernym distance to a root, root = 1. WordNet nouns form a DAG (no cycles);
  // the guard only protects against a corrupt database.
  int depth(long off, int guard = 0) {
    auto it = depth_.find(off);
    if (it != depth_.end()) return it->second;
    const std::vector<long> hyp = synset(off).hypernyms;
    int d = 1;
    if (!hyp.empty() && guard < 64) {
      int best = 1 << 20;
      for (long h : hyp) best = std::min(best, depth(h, guard + 1));
      d = best + 1;
    }
    depth_[off] = d;
    return d;
  }

  const std::vector<long>& ancestors(long off) {
    auto it = ancestors_.find(off);
    if (it != ancestors_.end()) return it->second;
    std::vector<long> out;
    std::unordered_set<long> seen;
    std::vector<long> stack{off};
    while (!stack.empty() && out.size() < 256) {
      const long s = stack.back();
      stack.pop_back();
      if (!seen.insert(s).second) continue;
      out.push_back(s);
      for (long h : synset(s).hypernyms) stack.push_back(h);
    }
    return ancestors_.emplace(off, std::move(out)).first->second;
  }

  // Offsets of the senses of an exact index word (lower case, '_' for spaces), frequency order.
  std::vector<long> senses(const std::string& word) {
    auto it = nouns_.find(word);
    if (it != nouns_.end()) return it->second;
    std::vector<long> offs;
    if (!word.empty() && word.size() < WORDBUF - 1) {
      std::vector<char> buf(word.begin(), word.end());
      buf.push_back('\0');
      IndexPtr idx = index_lookup(buf.data(), NOUN);
      if (idx) {
        for (int i = 0; i < idx->off_cnt; ++i) offs.push_back(long(idx->offset[i]));
        free_index(idx);
      }
    }
    nouns_[word] = offs;
    return offs;
  }

  // Base forms by WordNet morphology ("chairs" -> "chair", "mice" -> "mouse").
  std::vector<std::string> baseForms(const std::string& word) {
    std::vector<std::string> out;
    if (word.empty() || word.size() >= WORDBUF - 1) return out;
    std::vector<char> buf(word.begin(), word.end());
    buf.push_back('\0');
    for (char* m = morphstr(buf.data(), NOUN); m && out.size() < 8; m = morphstr(nullptr, NOUN))
      out.emplace_back(m);
    return out;
  }

  bool hasAncestor(long off, long anchor) {
    if (anchor < 0) return false;
    const auto& a = ancestors(off);
    return std::find(a.begin(), a.end(), anchor) != a.end();
  }

  // Rooms, buildings and building complexes: what an object label should not mean.
  bool isPlace(long off) {
    return hasAncestor(off, room) || hasAncestor(off, building) || hasAncestor(off, complex);
  }

  long artifact = -1, physical = -1, room = -1, building = -1, complex = -1;

 private:
  void resolveAnchorsLocked() {
    auto first = [&](const char* w) {
      const auto s = senses(w);
      return s.empty() ? -1L : s.front();
    };
    artifact = first("artifact");
    physical = first("physical_entity");
    room = first("room");
    building = first("building");
    complex = first("building_complex");
  }

  bool tried_ = false, open_ = false, initialised_ = false;
  std::filesystem::path dir_;
  std::unordered_map<long, SynsetData> synsets_;
  std::unordered_map<long, int> depth_;
  std::unordered_map<long, std::vector<long>> ancestors_;
  std::unordered_map<std::string, std::vector<long>> nouns_;

 public:
  std::unordered_map<std::string, VerbKin> kin;  // verbKin() answers, by lower-case word
  std::unordered_map<std::string, bool> noun_of_verb;                          // "label|verb"
  std::unordered_map<std::string, std::vector<std::string>> verb_ancestors;  // "verb|levels"
};

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string underscoresToSpaces(std::string s) {
  std::replace(s.begin(), s.end(), '_', ' ');
  return s;
}

// "(a piece of furniture ...; \"she sat on the bed\")" -> "a piece of furniture ..."
// Glosses may open with their own parenthesis: "((botany) a living organism ...)".
std::string cleanGloss(std::string g) {
  auto trimBack = [&] {
    while (!g.empty() && (g.back() == ' ' || g.back() == '\n')) g.pop_back();
  };
  while (!g.empty() && g.front() == ' ') g.erase(g.begin());
  if (!g.empty() && g.front() == '(') g.erase(g.begin());
  const auto quote = g.find("; \"");
  if (quote != std::string::npos) g.erase(quote);
  trimBack();
  if (!g.empty() && g.back() == ')' &&
      std::count(g.begin(), g.end(), ')') > std::count(g.begin(), g.end(), '('))
    g.pop_back();
  trimBack();
  return g;
}

bool isProperOnly(const SynsetData& d, const std::string& word) {
  bool lower_form = false, upper_form = false;
  for (const auto& w : d.words) {
    if (lower(w) != word) continue;
    const bool has_upper = std::any_of(w.begin(), w.end(), [](char c) { return std::isupper(static_cast<unsigned char>(c)); });
    (has_upper ? upper_form : lower_form) = true;
  }
  return upper_form && !lower_form;
}

// Picks the household sense (see lookupNoun in the header). Lower tier = better.
long chooseSense(Db& db, const std::vector<long>& offs, const std::string& word) {
  long best = -1;
  int best_tier = 1 << 20;
  for (long off : offs) {
    int tier;
    const bool place = db.isPlace(off);
    if (db.hasAncestor(off, db.artifact) && !place) tier = 0;
    else if (db.hasAncestor(off, db.physical) && !place) tier = 1;
    else if (place) tier = 2;
    else tier = 3;
    if (isProperOnly(db.synset(off), word)) tier += 4;
    if (tier < best_tier) best_tier = tier, best = off;
  }
  return best;
}

Sense makeSense(Db& db, long off) {
  Sense s;
  const SynsetData& d = db.synset(off);
  s.offset = off;
  for (const auto& w : d.words) s.lemmas.push_back(underscoresToSpaces(w));
  s.lemma = s.lemmas.empty() ? std::string() : s.lemmas.front();
  s.gloss = cleanGloss(d.gloss);
  s.lexfile = (d.fnum >= 0 && d.fnum < MAXFNUM && lexfiles[d.fnum]) ? lexfiles[d.fnum] : "";
  s.depth = db.depth(off);
  const std::vector<long> anc = db.ancestors(off);  // copy: depth() may grow the caches
  for (long a : anc) s.ancestors.push_back({a, db.depth(a)});
  return s;
}

std::optional<Sense> lookupNounLocked(Db& db, const std::string& raw) {
  std::string word = lower(raw);
  for (char& c : word)
    if (c == ' ' || c == '-') c = '_';
  if (word.empty()) return std::nullopt;
  std::vector<long> offs = db.senses(word);
  if (offs.empty())
    for (const auto& base : db.baseForms(word)) {
      offs = db.senses(base);
      if (!offs.empty()) {
        word = base;
        break;
      }
    }
  if (offs.empty()) return std::nullopt;
  long best = chooseSense(db, offs, word);
  // A plural that WordNet also lists as a word of its own in no physical sense ("shoes": "a
  // particular situation", as in someone's shoes) means the thing its base form names.
  if (!db.hasAncestor(best, db.physical))
    for (const auto& base : db.baseForms(word))
      if (base != word)
        if (const auto b = db.senses(base); !b.empty())
          if (const long off = chooseSense(db, b, base); db.hasAncestor(off, db.physical) && !db.isPlace(off)) {
            best = off;
            break;
          }
  return makeSense(db, best);
}

struct Resolved {
  Sense sense;
  std::vector<std::string> modifiers;
};

std::optional<Resolved> resolveLocked(Db& db, const std::string& label) {
  const auto tokens = labelTokens(label);
  if (tokens.empty()) return std::nullopt;
  if (tokens.size() > 1) {
    std::string underscored, joined;
    for (size_t i = 0; i < tokens.size(); ++i) {
      underscored += (i ? "_" : "") + tokens[i];
      joined += tokens[i];
    }
    for (const auto& w : {underscored, joined})
      if (auto s = lookupNounLocked(db, w)) return Resolved{*s, {}};
  }
  if (auto s = lookupNounLocked(db, tokens.back()))
    return Resolved{*s, std::vector<std::string>(tokens.begin(), tokens.end() - 1)};
  return std::nullopt;
}

// Runs `f(db)` under the lock when the database is open; otherwise returns `fallback`.
template <class F, class R>
R withDb(F&& f, R fallback) {
  Db& db = Db::get();
  std::lock_guard<std::mutex> lock(db.mutex);
  if (!db.openLocked()) return fallback;
  return f(db);
}

}  // namespace

bool available() {
  Db& db = Db::get();
  std::lock_guard<std::mutex> lock(db.mutex);
  return db.openLocked();
}

std::filesystem::path searchDir() {
  Db& db = Db::get();
  std::lock_guard<std::mutex> lock(db.mutex);
  db.openLocked();
  return db.dir();
}

bool reopen(const std::filesystem::path& dir) {
  Db& db = Db::get();
  std::lock_guard<std::mutex> lock(db.mutex);
  return db.reopenLocked(dir);
}

std::vector<std::string> labelTokens(const std::string& label) {
  std::vector<std::string> out;
  std::string cur;
  auto flush = [&] {
    if (!cur.empty()) out.push_back(lower(cur));
    cur.clear();
  };
  for (size_t i = 0; i < label.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(label[i]);
    if (!std::isalnum(c)) {
      flush();
      continue;
    }
    if (std::isupper(c) && !cur.empty()) {
      const unsigned char prev = static_cast<unsigned char>(cur.back());
      const bool next_lower = i + 1 < label.size() && std::islower(static_cast<unsigned char>(label[i + 1]));
      // "armChair" | "TVStand" -> split before 'C' and before 'S'
      if (std::islower(prev) || std::isdigit(prev) || (std::isupper(prev) && next_lower)) flush();
    }
    cur.push_back(char(c));
  }
  flush();
  return out;
}

std::optional<Sense> lookupNoun(const std::string& word) {
  return withDb([&](Db& db) { return lookupNounLocked(db, word); }, std::optional<Sense>{});
}

bool knownAsVerb(const std::string& word) {
  const std::string w = lower(word);
  if (w.empty() || w.size() >= WORDBUF - 1 || w.find(' ') != std::string::npos) return false;
  return withDb(
      [&](Db&) {
        const auto indexed = [](const std::string& v) {
          std::vector<char> buf(v.begin(), v.end());
          buf.push_back('\0');
          IndexPtr idx = index_lookup(buf.data(), VERB);
          if (!idx) return false;
          free_index(idx);
          return true;
        };
        if (indexed(w)) return true;
        std::vector<char> buf(w.begin(), w.end());
        buf.push_back('\0');
        for (char* m = morphstr(buf.data(), VERB); m; m = morphstr(nullptr, VERB))
          if (indexed(m)) return true;
        return false;
      },
      false);
}

std::string actGlossOf(const std::string& word) {
  return withDb(
      [&](Db& db) -> std::string {
        std::string w = lower(word);
        if (w.empty() || w.find(' ') != std::string::npos) return {};
        std::vector<long> offs = db.senses(w);
        if (offs.empty())
          for (const auto& base : db.baseForms(w))
            if (offs = db.senses(base); !offs.empty()) break;
        for (long off : offs) {
          const SynsetData& d = db.synset(off);
          if (d.fnum >= 0 && d.fnum < MAXFNUM && lexfiles[d.fnum] && std::string(lexfiles[d.fnum]) == "noun.act")
            return cleanGloss(d.gloss);
        }
        return {};
      },
      std::string());
}

std::string verbGlossOf(const std::string& word) {
  const std::string w = lower(word);
  if (w.empty() || w.size() >= WORDBUF - 1 || w.find(' ') != std::string::npos) return {};
  return withDb(
      [&](Db&) -> std::string {
        const auto firstSense = [](const std::string& v) -> std::string {
          std::vector<char> buf(v.begin(), v.end());
          buf.push_back('\0');
          IndexPtr idx = index_lookup(buf.data(), VERB);
          if (!idx) return {};
          std::string gloss;
          if (idx->off_cnt > 0) {
            char empty[1] = {0};
            if (SynsetPtr s = read_synset(VERB, idx->offset[0], empty)) {
              gloss = cleanGloss(s->defn ? s->defn : "");
              free_synset(s);
            }
          }
          free_index(idx);
          return gloss;
        };
        if (std::string g = firstSense(w); !g.empty()) return g;
        std::vector<char> buf(w.begin(), w.end());
        buf.push_back('\0');
        for (char* m = morphstr(buf.data(), VERB); m; m = morphstr(nullptr, VERB))
          if (std::string g = firstSense(m); !g.empty()) return g;
        return {};
      },
      std::string());
}

namespace {

// Adds the words of synset (pos, offset) to `out`: all of them, or only the `which`-th (1-based).
void addSynsetWords(int pos, long offset, int which, std::vector<std::string>& out) {
  char empty[1] = {0};
  SynsetPtr s = read_synset(pos, offset, empty);
  if (!s) return;
  for (int i = 0; i < s->wcount; ++i)
    if (which <= 0 || which == i + 1) {
      std::string w = underscoresToSpaces(lower(s->words[i]));
      if (std::find(out.begin(), out.end(), w) == out.end()) out.push_back(std::move(w));
    }
  free_synset(s);
}

VerbKin verbKinLocked(const std::string& v) {
  VerbKin k;
  std::vector<char> buf(v.begin(), v.end());
  buf.push_back('\0');
  IndexPtr idx = index_lookup(buf.data(), VERB);
  if (!idx) return k;
  char empty[1] = {0};
  for (int sense = 0; sense < std::min(idx->off_cnt, 2); ++sense) {
    SynsetPtr s = read_synset(VERB, idx->offset[sense], empty);
    if (!s) continue;
    if (sense == 0) addSynsetWords(VERB, idx->offset[0], 0, k.verbs);
    for (int i = 0; i < s->ptrcount; ++i) {
      if (sense == 0 && s->ptrtyp[i] == HYPERPTR && s->ppos[i] == VERB) addSynsetWords(VERB, s->ptroff[i], 1, k.verbs);
      // A derivation is lexical: from one word of this synset to one of the other's.
      if (s->ptrtyp[i] == DERIVATION && s->ppos[i] == NOUN) addSynsetWords(NOUN, s->ptroff[i], s->pto[i], k.nouns);
    }
    free_synset(s);
  }
  free_index(idx);
  return k;
}

}  // namespace

VerbKin verbKin(const std::string& word) {
  const std::string w = lower(word);
  if (w.empty() || w.size() >= WORDBUF - 1 || w.find(' ') != std::string::npos) return {};
  return withDb(
      [&](Db& db) -> VerbKin {
        if (const auto it = db.kin.find(w); it != db.kin.end()) return it->second;
        VerbKin k = verbKinLocked(w);
        if (k.verbs.empty()) {
          std::vector<char> buf(w.begin(), w.end());
          buf.push_back('\0');
          std::vector<std::string> bases;
          for (char* m = morphstr(buf.data(), VERB); m; m = morphstr(nullptr, VERB)) bases.emplace_back(m);
          for (const auto& b : bases)
            if (k = verbKinLocked(b); !k.verbs.empty()) break;
        }
        return db.kin.emplace(w, std::move(k)).first->second;
      },
      VerbKin{});
}

bool nounOfVerb(const std::string& label, const std::string& verb) {
  const std::string key = lower(label) + "|" + lower(verb);
  if (const auto hit = withDb(
          [&](Db& db) -> std::optional<bool> {
            const auto it = db.noun_of_verb.find(key);
            return it == db.noun_of_verb.end() ? std::nullopt : std::optional<bool>(it->second);
          },
          std::optional<bool>{}))
    return *hit;
  const auto sense = lookupLabel(label);
  const std::string v = lower(verb);
  if (!sense || v.empty() || v.size() >= WORDBUF - 1) return false;
  return withDb(
      [&](Db& db) {
        std::string form = v;
        std::replace(form.begin(), form.end(), ' ', '_');
        char empty[1] = {0};
        SynsetPtr s = read_synset(NOUN, sense->offset, empty);
        if (!s) return false;
        bool found = false;
        for (int i = 0; i < s->ptrcount && !found; ++i) {
          if (s->ptrtyp[i] != DERIVATION || s->ppos[i] != VERB) continue;
          SynsetPtr t = read_synset(VERB, s->ptroff[i], empty);
          if (!t) continue;
          // A derivation is lexical: it joins one word of each synset (pto, 1-based; 0 = all).
          for (int k = 0; k < t->wcount && !found; ++k)
            found = (s->pto[i] <= 0 || s->pto[i] == k + 1) && lower(t->words[k]) == form;
          free_synset(t);
        }
        free_synset(s);
        db.noun_of_verb[key] = found;
        return found;
      },
      false);
}

namespace {

// Base forms of a verb: itself when indexed, else what verb morphology gives ("lying" -> "lie").
std::vector<std::string> verbBasesLocked(const std::string& w) {
  std::vector<std::string> out;
  if (w.empty() || w.size() >= WORDBUF - 1) return out;
  std::vector<char> buf(w.begin(), w.end());
  buf.push_back('\0');
  if (IndexPtr idx = index_lookup(buf.data(), VERB)) {
    free_index(idx);
    out.push_back(w);
  }
  for (char* m = morphstr(buf.data(), VERB); m && out.size() < 8; m = morphstr(nullptr, VERB))
    if (std::find(out.begin(), out.end(), std::string(m)) == out.end()) out.emplace_back(m);
  return out;
}

}  // namespace

std::vector<std::string> verbAncestors(const std::string& verb, int levels) {
  const std::string w = lower(verb);
  if (w.empty() || w.find(' ') != std::string::npos || levels <= 0) return {};
  return withDb(
      [&](Db& db) -> std::vector<std::string> {
        const std::string key = w + "|" + std::to_string(levels);
        if (const auto it = db.verb_ancestors.find(key); it != db.verb_ancestors.end()) return it->second;
        std::vector<std::string> out;
        char empty[1] = {0};
        for (const auto& base : verbBasesLocked(w)) {
          std::vector<char> buf(base.begin(), base.end());
          buf.push_back('\0');
          IndexPtr idx = index_lookup(buf.data(), VERB);
          if (!idx) continue;
          long off = idx->off_cnt > 0 ? long(idx->offset[0]) : -1;
          free_index(idx);
          for (int level = 0; level < levels && off >= 0; ++level) {
            SynsetPtr s = read_synset(VERB, off, empty);
            if (!s) break;
            off = -1;
            for (int i = 0; i < s->ptrcount; ++i)
              if (s->ptrtyp[i] == HYPERPTR && s->ppos[i] == VERB) {
                off = long(s->ptroff[i]);
                break;
              }
            free_synset(s);
            if (off >= 0) addSynsetWords(VERB, off, 0, out);
          }
          break;
        }
        return db.verb_ancestors.emplace(key, std::move(out)).first->second;
      },
      std::vector<std::string>{});
}

std::string phrasalVerb(const std::string& verb, const std::string& particle) {
  const std::string w = lower(verb), p = lower(particle);
  if (w.empty() || p.empty() || w.find(' ') != std::string::npos || p.find(' ') != std::string::npos) return {};
  return withDb(
      [&](Db&) -> std::string {
        for (const auto& base : verbBasesLocked(w)) {
          const std::string form = base + "_" + p;
          if (form.size() >= WORDBUF - 1) continue;
          std::vector<char> buf(form.begin(), form.end());
          buf.push_back('\0');
          if (IndexPtr idx = index_lookup(buf.data(), VERB)) {
            free_index(idx);
            return base + " " + p;
          }
        }
        return {};
      },
      std::string());
}

std::vector<std::string> nounForms(const std::string& word) {
  std::string w = lower(word);
  std::replace(w.begin(), w.end(), ' ', '_');
  return withDb(
      [&](Db& db) -> std::vector<std::string> {
        std::vector<std::string> out;
        if (!db.senses(w).empty()) out.push_back(underscoresToSpaces(w));
        for (const auto& base : db.baseForms(w))
          if (!db.senses(base).empty() && std::find(out.begin(), out.end(), underscoresToSpaces(base)) == out.end())
            out.push_back(underscoresToSpaces(base));
        return out;
      },
      std::vector<std::string>{});
}

bool namesPlace(const std::string& label) {
  const auto sense = lookupLabel(label);
  return sense && withDb([&](Db& db) { return db.isPlace(sense->offset); }, false);
}

std::vector<std::string> adjectiveGlossesOf(const std::string& word, int senses) {
  const std::string w = lower(word);
  if (w.empty() || w.size() >= WORDBUF - 1 || w.find(' ') != std::string::npos || senses <= 0) return {};
  return withDb(
      [&](Db&) -> std::vector<std::string> {
        std::vector<std::string> out;
        std::vector<char> buf(w.begin(), w.end());
        buf.push_back('\0');
        IndexPtr idx = index_lookup(buf.data(), ADJ);
        if (!idx) return out;
        char empty[1] = {0};
        for (int i = 0; i < std::min(idx->off_cnt, senses); ++i)
          if (SynsetPtr s = read_synset(ADJ, idx->offset[i], empty)) {
            out.push_back(cleanGloss(s->defn ? s->defn : ""));
            free_synset(s);
          }
        free_index(idx);
        return out;
      },
      std::vector<std::string>{});
}

namespace {

// The senses of the index word lookupNoun() read `word` from, and where its pick is among them:
// "hands" has senses of its own (guardianship, a crew), but the thing it names is read from
// "hand". Empty offsets when the word is no noun.
std::pair<std::vector<long>, int> pickedAmongSensesLocked(Db& db, const std::string& word) {
  const auto picked = lookupNounLocked(db, word);
  if (!picked) return {{}, -1};
  std::string w = lower(word);
  std::replace(w.begin(), w.end(), ' ', '_');
  std::vector<std::string> forms{w};
  for (const auto& base : db.baseForms(w)) forms.push_back(base);
  for (const auto& form : forms) {
    std::vector<long> offs = db.senses(form);
    const auto at = std::find(offs.begin(), offs.end(), picked->offset);
    if (at == offs.end()) continue;
    const int rank = int(at - offs.begin());
    return {std::move(offs), rank};
  }
  return {{}, -1};
}

}  // namespace

std::string usualNounLexfile(const std::string& word) {
  return withDb(
      [&](Db& db) -> std::string {
        const auto [offs, rank] = pickedAmongSensesLocked(db, word);
        if (offs.empty()) return {};
        const SynsetData& d = db.synset(offs.front());  // the most frequent sense
        return d.fnum >= 0 && d.fnum < MAXFNUM && lexfiles[d.fnum] ? lexfiles[d.fnum] : "";
      },
      std::string());
}

int pickedSenseRank(const std::string& word) {
  return withDb([&](Db& db) { return pickedAmongSensesLocked(db, word).second; }, -1);
}

bool namesAnimal(const std::string& word) {
  return withDb(
      [&](Db& db) {
        std::string w = lower(word);
        std::vector<long> offs = db.senses(w);
        if (offs.empty())
          for (const auto& base : db.baseForms(w))
            if (offs = db.senses(base); !offs.empty()) break;
        if (offs.empty()) return false;
        const SynsetData& d = db.synset(offs.front());  // the most frequent sense
        return d.fnum >= 0 && d.fnum < MAXFNUM && lexfiles[d.fnum] && std::string(lexfiles[d.fnum]) == "noun.animal";
      },
      false);
}

std::optional<Sense> lookupLabel(const std::string& label) {
  return withDb(
      [&](Db& db) -> std::optional<Sense> {
        auto r = resolveLocked(db, label);
        if (!r) return std::nullopt;
        return r->sense;
      },
      std::optional<Sense>{});
}

std::optional<LabelSense> resolveLabel(const std::string& label) {
  return withDb(
      [&](Db& db) -> std::optional<LabelSense> {
        auto r = resolveLocked(db, label);
        if (!r) return std::nullopt;
        return LabelSense{std::move(r->sense), std::move(r->modifiers)};
      },
      std::optional<LabelSense>{});
}

std::string glossOf(const std::string& label) {
  auto s = lookupLabel(label);
  return s ? s->gloss : std::string();
}

std::vector<std::string> hypernymsOf(const std::string& label) {
  return withDb(
      [&](Db& db) {
        std::vector<std::string> out;
        auto r = resolveLocked(db, label);
        if (!r) return out;
        long cur = r->sense.offset;
        for (int guard = 0; guard < 64; ++guard) {
          const auto hyp = db.synset(cur).hypernyms;
          if (hyp.empty()) break;
          long next = hyp.front();
          for (long h : hyp)
            if (db.depth(h) < db.depth(next)) next = h;
          const auto& words = db.synset(next).words;
          out.push_back(words.empty() ? std::string() : underscoresToSpaces(words.front()));
          cur = next;
        }
        return out;
      },
      std::vector<std::string>{});
}

std::vector<std::string> synonymsOf(const std::string& label) {
  auto s = lookupLabel(label);
  return s ? s->lemmas : std::vector<std::string>{};
}

std::optional<double> wuPalmer(const std::string& a, const std::string& b) {
  const auto sa = lookupLabel(a), sb = lookupLabel(b);
  if (!sa || !sb) return std::nullopt;
  int lcs = 0;
  for (const auto& x : sa->ancestors)
    for (const auto& y : sb->ancestors)
      if (x.offset == y.offset) lcs = std::max(lcs, x.depth);
  return 2.0 * lcs / double(sa->depth + sb->depth);
}

}  // namespace ussnav::wordnet
