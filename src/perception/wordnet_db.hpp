#pragma once
// Internal to the WordNet reader (wordnet.cpp: noun senses and labels; wordnet_verbs.cpp: verbs,
// acts and adjectives): the one process-wide database handle with its caches, behind one mutex
// (the C library keeps global state), and the text helpers both files use.

#include <spdlog/spdlog.h>
#include <wn.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "ussnav/perception/wordnet.hpp"

namespace ussnav::wordnet::detail {

// The library prints errors through this hook; route them to the debug log instead of stderr.
inline int quietMessage(char* msg) {
  spdlog::debug("wordnet: {}", msg ? msg : "");
  return -1;
}

struct SynsetData {
  std::vector<std::string> words;
  std::string gloss;
  int fnum = 0;
  std::vector<long> hypernyms;
  std::vector<long> hyponyms;  // direct ones, not instances
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
        else if (s->ptrtyp[i] == HYPOPTR && s->ppos[i] == NOUN)
          d.hyponyms.push_back(s->ptroff[i]);
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

  // Furniture, fixtures and home appliances: what a room is furnished with.
  bool isFurnishing(long off) {
    return hasAncestor(off, furniture) || hasAncestor(off, fixture) || hasAncestor(off, appliance);
  }

  long artifact = -1, physical = -1, room = -1, building = -1, complex = -1;
  long furniture = -1, fixture = -1, appliance = -1;

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
    furniture = first("furniture");
    fixture = first("fixture");
    appliance = first("home_appliance");
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

std::string lower(std::string s);
std::string underscoresToSpaces(std::string s);
// "(a piece of furniture ...; \"she sat on the bed\")" -> "a piece of furniture ..."
std::string cleanGloss(std::string g);

// Runs `f(db)` under the lock when the database is open; otherwise returns `fallback`.
template <class F, class R>
R withDb(F&& f, R fallback) {
  Db& db = Db::get();
  std::lock_guard<std::mutex> lock(db.mutex);
  if (!db.openLocked()) return fallback;
  return f(db);
}

}  // namespace ussnav::wordnet::detail
