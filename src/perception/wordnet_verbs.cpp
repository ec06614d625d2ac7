// Verbs, acts and adjectives of WordNet (see ussnav/perception/wordnet.hpp): what the
// instruction reader needs beyond noun senses.

#include <cstring>

#include "ussnav/perception/wordnet.hpp"

#include "wordnet_db.hpp"

namespace ussnav::wordnet {

using namespace detail;

namespace {

// The verbs WordNet indexes that a word is: itself, and what verb morphology makes of it
// ("lying" -> "lie", "ate" -> "eat"). Empty when none.
std::vector<std::string> verbBasesLocked(const std::string& w) {
  std::vector<std::string> out;
  if (w.empty() || w.size() >= WORDBUF - 1) return out;
  const auto indexed = [](const std::string& v) {
    std::vector<char> buf(v.begin(), v.end());
    buf.push_back('\0');
    IndexPtr idx = index_lookup(buf.data(), VERB);
    if (idx) free_index(idx);
    return idx != nullptr;
  };
  if (indexed(w)) out.push_back(w);
  std::vector<char> buf(w.begin(), w.end());
  buf.push_back('\0');
  for (char* m = morphstr(buf.data(), VERB); m && out.size() < 8; m = morphstr(nullptr, VERB))
    if (std::find(out.begin(), out.end(), std::string(m)) == out.end() && indexed(m)) out.emplace_back(m);
  return out;
}

// The adjective index entry of w (the caller frees it), with `morph` of its base form when w
// itself is none ("sleepier" -> sleepy); nullptr when none.
IndexPtr adjectiveIndexLocked(const std::string& w, bool morph) {
  std::vector<char> buf(w.begin(), w.end());
  buf.push_back('\0');
  IndexPtr idx = index_lookup(buf.data(), ADJ);
  if (!idx && morph)
    if (char* base = morphstr(buf.data(), ADJ)) {
      std::vector<char> b(base, base + std::strlen(base) + 1);
      idx = index_lookup(b.data(), ADJ);
    }
  return idx;
}

// Definitions of the first `senses` senses of index entry `idx` of part of speech `pos`, most
// frequent first; frees idx.
std::vector<std::string> glossesLocked(IndexPtr idx, int pos, int senses) {
  std::vector<std::string> out;
  if (!idx) return out;
  char empty[1] = {0};
  for (int i = 0; i < std::min(idx->off_cnt, senses); ++i)
    if (SynsetPtr s = read_synset(pos, idx->offset[i], empty)) {
      out.push_back(cleanGloss(s->defn ? s->defn : ""));
      free_synset(s);
    }
  free_index(idx);
  return out;
}

}  // namespace

bool knownAsVerb(const std::string& word) {
  const std::string w = lower(word);
  if (w.empty() || w.find(' ') != std::string::npos) return false;
  return withDb([&](Db&) { return !verbBasesLocked(w).empty(); }, false);
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
  const auto glosses = verbGlossesOf(word, 1);
  return glosses.empty() ? std::string() : glosses.front();
}

std::vector<std::string> verbGlossesOf(const std::string& word, int senses) {
  const std::string w = lower(word);
  if (w.empty() || w.size() >= WORDBUF - 1 || w.find(' ') != std::string::npos || senses <= 0) return {};
  return withDb(
      [&](Db&) -> std::vector<std::string> {
        for (const auto& base : verbBasesLocked(w)) {
          std::vector<char> buf(base.begin(), base.end());
          buf.push_back('\0');
          if (auto out = glossesLocked(index_lookup(buf.data(), VERB), VERB, senses); !out.empty() && !out[0].empty())
            return out;
        }
        return std::vector<std::string>{};
      },
      std::vector<std::string>{});
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
        VerbKin k;
        for (const auto& base : verbBasesLocked(w))
          if (k = verbKinLocked(base); !k.verbs.empty()) break;
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

std::vector<std::string> adjectiveGlossesOf(const std::string& word, int senses) {
  const std::string w = lower(word);
  if (w.empty() || w.size() >= WORDBUF - 1 || w.find(' ') != std::string::npos || senses <= 0) return {};
  return withDb(
      [&](Db&) -> std::vector<std::string> {
        return glossesLocked(adjectiveIndexLocked(w, false), ADJ, senses);
      },
      std::vector<std::string>{});
}

namespace {

// A synset's words as the reader writes them: "played_out" -> "played out", "asleep(p)" -> "asleep".
std::vector<std::string> synsetWords(const Synset& s) {
  std::vector<std::string> out;
  for (int i = 0; i < s.wcount; ++i) {
    std::string w = s.words[i] ? s.words[i] : "";
    if (const auto paren = w.find('('); paren != std::string::npos) w.erase(paren);
    std::replace(w.begin(), w.end(), '_', ' ');
    if (!w.empty()) out.push_back(lower(w));
  }
  return out;
}

}  // namespace

std::vector<std::vector<std::string>> adjectiveClustersOf(const std::string& word, int senses) {
  const std::string w = lower(word);
  if (w.empty() || w.size() >= WORDBUF - 1 || w.find(' ') != std::string::npos || senses <= 0) return {};
  return withDb(
      [&](Db&) -> std::vector<std::vector<std::string>> {
        std::vector<std::vector<std::string>> out;
        IndexPtr idx = adjectiveIndexLocked(w, true);
        if (!idx) return out;
        char empty[1] = {0};
        for (int i = 0; i < std::min(idx->off_cnt, senses); ++i) {
          SynsetPtr s = read_synset(ADJ, idx->offset[i], empty);
          if (!s) continue;
          std::vector<std::string> words = synsetWords(*s);
          if (s->pos && std::string(s->pos) == "s")
            for (int k = 0; k < s->ptrcount; ++k)
              if (s->ptrtyp[k] == SIMPTR) {
                if (SynsetPtr head = read_synset(ADJ, s->ptroff[k], empty)) {
                  for (auto& h : synsetWords(*head)) words.push_back(std::move(h));
                  free_synset(head);
                }
                break;
              }
          free_synset(s);
          out.push_back(std::move(words));
        }
        free_index(idx);
        return out;
      },
      std::vector<std::vector<std::string>>{});
}

}  // namespace ussnav::wordnet
