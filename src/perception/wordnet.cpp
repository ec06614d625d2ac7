#include "ussnav/perception/wordnet.hpp"

#include "wordnet_db.hpp"

namespace ussnav::wordnet {

namespace detail {

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string underscoresToSpaces(std::string s) {
  std::replace(s.begin(), s.end(), '_', ' ');
  return s;
}

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

}  // namespace detail

using namespace detail;

namespace {

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

bool furnishes(const std::string& label) {
  const auto sense = lookupLabel(label);
  return sense && withDb([&](Db& db) { return db.isFurnishing(sense->offset); }, false);
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

std::vector<std::string> kindGlossesOf(const std::string& label) {
  return withDb(
      [&](Db& db) {
        std::vector<std::string> out;
        const auto r = resolveLocked(db, label);
        if (!r || !r->modifiers.empty()) return out;
        const std::vector<long> kinds = db.synset(r->sense.offset).hyponyms;  // copy: synset() may grow the cache
        for (long k : kinds) out.push_back(cleanGloss(db.synset(k).gloss));
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
