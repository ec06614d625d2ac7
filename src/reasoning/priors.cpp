// Loading and combining the commonsense tables (see priors.hpp).

#include "ussnav/reasoning/priors.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "ussnav/core/error.hpp"
#include "request_words.hpp"
#include "ussnav/perception/wordnet.hpp"

namespace ussnav {
namespace {

// Loosest label -> category match. Between 0.6 and 0.7 the WordNet encoder's nearest category
// was another object in about 9 of 10 labels tried (shelf -> toilet paper hanger, dishwasher ->
// washing machine, wardrobe -> cabinet, keyboard -> remote control); from 0.7 up it was mostly
// the thing itself (refrigerator -> fridge 0.76, recliner -> arm chair 0.80, bunk bed -> bed).
constexpr double kNearCosine = 0.7;
// Verb senses read for a participle's state (CommonsensePriors::stateFor): "baking" is "be very
// hot" in its fourth.
constexpr int kStateVerbSenses = 4;

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  std::stringstream ss(s);
  while (std::getline(ss, cur, sep)) {
    if (!cur.empty() && cur.back() == '\r') cur.pop_back();
    out.push_back(cur);
  }
  return out;
}

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

// Non-comment, non-empty lines of a table, split by `sep`; the first is the header.
std::vector<std::vector<std::string>> readTable(const std::filesystem::path& p, char sep) {
  std::ifstream in(p);
  if (!in) throw InputError(p.string(), "", "cannot read the priors table (expected it in data/priors/)");
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (trim(line).empty() || line[0] == '#') continue;
    rows.push_back(split(line, sep));
  }
  if (rows.size() < 2) throw InputError(p.string(), "", "expected a header and at least one row");
  return rows;
}

double number(const std::filesystem::path& p, size_t line, const std::string& col, const std::string& s) {
  try {
    size_t used = 0;
    const double v = std::stod(s, &used);
    if (used == s.size() && std::isfinite(v)) return v;
  } catch (const std::exception&) {
  }
  throw InputError(p.string(), "row " + std::to_string(line) + ", column " + col, "'" + s + "' is not a number");
}

// A name with its spaces, underscores and hyphens dropped: "armchair" names ArmChair ("arm chair"),
// "nightstand" the alias "night stand".
std::string joined(const std::string& s) {
  std::string out;
  for (char c : s)
    if (c != ' ' && c != '_' && c != '-') out += c;
  return out;
}

void normalise(std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x;
  if (s > 0.0)
    for (double& x : v) x /= s;
}

}  // namespace

std::string categoryWords(const std::string& name) {
  std::string out;
  for (const auto& t : wordnet::labelTokens(name)) out += (out.empty() ? "" : " ") + t;
  return out;
}

std::filesystem::path CommonsensePriors::defaultDir() {
  namespace fs = std::filesystem;
  for (fs::path p : {fs::path("data/priors"), fs::path(USSNAV_SOURCE_DIR) / "data/priors"}) {
    std::error_code ec;
    if (fs::exists(p / "room_types.tsv", ec)) return p;
  }
  return {};
}

std::shared_ptr<const CommonsensePriors> CommonsensePriors::load(const std::filesystem::path& dir, std::shared_ptr<const TextEncoder> encoder,
                                          double match_cosine) {
  auto P = std::make_shared<CommonsensePriors>();
  P->encoder_ = std::move(encoder);
  P->match_cosine_ = match_cosine;
  if (dir.empty()) throw InputError("data/priors", "", "priors folder not found (run from the repository)");

  // Room types, and which table columns mean each.
  const auto rt_path = dir / "room_types.tsv";
  const auto rt = readTable(rt_path, '\t');
  std::map<std::string, int> sgnav_col, procthor_col;  // column name -> room index
  for (size_t i = 1; i < rt.size(); ++i) {
    if (rt[i].size() != 5) throw InputError(rt_path.string(), "row " + std::to_string(i), "expected 5 tab-separated columns");
    RoomType r;
    r.name = trim(rt[i][0]);
    for (const auto& a : split(rt[i][1], ','))
      if (!trim(a).empty()) r.aliases.push_back(trim(a));
    r.description = trim(rt[i][4]);
    if (trim(rt[i][2]) != "-") sgnav_col[trim(rt[i][2])] = int(P->rooms_.size());
    if (trim(rt[i][3]) != "-") procthor_col[trim(rt[i][3])] = int(P->rooms_.size());
    P->rooms_.push_back(r);
  }
  const size_t R = P->rooms_.size();

  // Adjacency prior.
  P->adjacency_.assign(R, std::vector<double>(R, 0.1));
  const auto adj_path = dir / "room_adjacency.tsv";
  const auto adj = readTable(adj_path, '\t');
  for (size_t i = 1; i < adj.size(); ++i) {
    if (adj[i].size() != 3) throw InputError(adj_path.string(), "row " + std::to_string(i), "expected room_a, room_b, weight");
    const int a = P->roomIndex(adj[i][0]), b = P->roomIndex(adj[i][1]);
    if (a < 0 || b < 0) throw InputError(adj_path.string(), "row " + std::to_string(i), "unknown room type (not in room_types.tsv)");
    const double w = number(adj_path, i, "weight", adj[i][2]);
    P->adjacency_[size_t(a)][size_t(b)] = P->adjacency_[size_t(b)][size_t(a)] = std::clamp(w, 0.0, 1.0);
  }

  // States and what they stand for.
  const auto st_path = dir / "states.tsv";
  const auto st = readTable(st_path, '\t');
  for (size_t i = 1; i < st.size(); ++i) {
    if (st[i].size() != 3 || trim(st[i][0]).empty() || trim(st[i][1]).empty() || trim(st[i][2]).empty())
      throw InputError(st_path.string(), "row " + std::to_string(i),
                       "expected state, request, act (three tab-separated fields; act '-' for none)");
    const std::string act = trim(st[i][2]);
    P->states_[lower(trim(st[i][0]))] = {trim(st[i][1]), act == "-" ? std::string() : lower(act)};
  }

  // ProcTHOR placement weights: 0 / 1 / 2 -> likelihood.
  const auto pt_path = dir / "procthor_object_room_weights.tsv";
  const auto pt = readTable(pt_path, '\t');
  std::vector<std::pair<size_t, int>> pt_cols;  // column -> room
  for (size_t c = 1; c < pt[0].size(); ++c)
    if (procthor_col.count(pt[0][c])) pt_cols.push_back({c, procthor_col[pt[0][c]]});
  if (pt_cols.empty()) throw InputError(pt_path.string(), "header", "no room column matches room_types.tsv");
  for (size_t i = 1; i < pt.size(); ++i) {
    Row row{categoryWords(pt[i][0]), {}, std::vector<double>(R, 0.0), {}};
    row.names = {row.category};
    bool any = false, blank = false;
    for (auto [c, r] : pt_cols) {
      if (c >= pt[i].size()) throw InputError(pt_path.string(), "row " + std::to_string(i), "too few columns");
      if (trim(pt[i][c]).empty()) blank = true;  // not annotated (Doorframe, Window): no prior
      if (blank) continue;
      const double w = number(pt_path, i, pt[0][c], pt[i][c]);
      any = any || w > 0.0;
      row.p[size_t(r)] = w >= 2.0 ? 1.0 : w >= 1.0 ? 0.35 : 0.03;
    }
    if (!any || blank) continue;  // says nothing (e.g. Television, placed through asset groups)
    normalise(row.p);
    P->rows_.push_back(std::move(row));
  }

  // SG-Nav co-occurrence: log-likelihood-like scores -> exp.
  const auto sg_path = dir / "sgnav_object_room_cooccurrence.csv";
  const auto sg = readTable(sg_path, ',');
  std::vector<std::pair<size_t, int>> sg_cols;
  for (size_t c = 1; c < sg[0].size(); ++c)
    if (sgnav_col.count(sg[0][c])) sg_cols.push_back({c, sgnav_col[sg[0][c]]});
  if (sg_cols.empty()) throw InputError(sg_path.string(), "header", "no room column matches room_types.tsv");
  // MP3D's mpcat40 table names the NYU40 classes and raw labels each SG-Nav category covers
  // (tv_monitor: television; chest_of_drawers: dresser, night stand): aliases for matching.
  std::map<std::string, std::vector<std::string>> aliases;
  const auto mp_path = dir / "mpcat40.tsv";
  const auto mp = readTable(mp_path, '\t');
  const auto col = [&](const std::string& name) {
    const auto it = std::find(mp[0].begin(), mp[0].end(), name);
    if (it == mp[0].end()) throw InputError(mp_path.string(), "header", "expected a column '" + name + "'");
    return size_t(it - mp[0].begin());
  };
  const size_t c_cat = col("mpcat40"), c_nyu = col("nyu40"), c_labels = col("labels");
  for (size_t i = 1; i < mp.size(); ++i) {
    if (mp[i].size() <= c_cat) continue;
    auto& a = aliases[categoryWords(mp[i][c_cat])];
    for (size_t c : {c_nyu, c_labels})
      if (c < mp[i].size())
        for (const auto& x : split(mp[i][c], ','))
          if (!trim(x).empty()) a.push_back(categoryWords(trim(x)));
  }
  for (size_t i = 1; i < sg.size(); ++i) {
    Row row{categoryWords(sg[i][0]), {}, std::vector<double>(R, 0.0), {}};
    row.names = {row.category};
    for (const auto& a : aliases[row.category])
      if (a != row.category) row.names.push_back(a);
    for (auto [c, r] : sg_cols) {
      if (c >= sg[i].size()) throw InputError(sg_path.string(), "row " + std::to_string(i), "too few columns");
      row.p[size_t(r)] = std::exp(std::clamp(number(sg_path, i, sg[0][c], sg[i][c]), -30.0, 30.0));
    }
    normalise(row.p);
    P->rows_.push_back(std::move(row));
  }
  for (const Row& r : P->rows_)
    if (std::find(P->categories_.begin(), P->categories_.end(), r.category) == P->categories_.end())
      P->categories_.push_back(r.category);

  // Matterport3D's raw labels -> mpcat40 ("nightstand" -> chest_of_drawers, "monitor" ->
  // tv_monitor): the annotators' own synonym table. Kept only where the category has a row.
  const auto map_path = dir / "mp3d_category_mapping.tsv";
  const auto mm = readTable(map_path, '\t');
  if (mm[0].size() != 4 || mm[0][0] != "raw_category" || mm[0][3] != "mpcat40")
    throw InputError(map_path.string(), "header", "expected raw_category, category, count, mpcat40");
  std::map<std::string, double> best_count;
  for (size_t i = 1; i < mm.size(); ++i) {
    if (mm[i].size() != 4) throw InputError(map_path.string(), "row " + std::to_string(i), "expected 4 tab-separated columns");
    const double count = number(map_path, i, "count", mm[i][2]);
    const std::string cat = categoryWords(trim(mm[i][3]));
    if (std::none_of(P->rows_.begin(), P->rows_.end(), [&](const Row& r) { return r.category == cat; })) continue;
    for (const std::string& label : {lower(trim(mm[i][0])), lower(trim(mm[i][1]))}) {
      if (label.empty()) continue;
      auto [it, fresh] = best_count.try_emplace(label, count);
      if (fresh || count > it->second) it->second = count, P->mp3d_[label] = cat;
    }
  }
  // Rows named for a kind made for another thing ("coffee machine"): their head noun's word.
  for (Row& r : P->rows_)
    for (const auto& name : r.names)
      r.kind_heads.push_back(P->forAThing(name) ? wordnet::labelTokens(name).back() : std::string());
  return P;
}

int CommonsensePriors::roomNamedBy(const std::string& word) const {
  // A room type's one-word name or alias ("office", "corridor"), else the first word of a
  // two-word one ("dining" room, "conference" room, "laundry" room, "exercise" room).
  const std::string w = lower(trim(word));
  if (w.empty()) return -1;
  int first_word = -1;
  for (size_t i = 0; i < rooms_.size(); ++i) {
    std::vector<std::string> names = rooms_[i].aliases;
    names.push_back(rooms_[i].name);
    for (const auto& n : names) {
      const auto t = wordnet::labelTokens(n);
      if (t.size() == 1 && t[0] == w) return int(i);
      if (t.size() == 2 && t[0] == w && first_word < 0) first_word = int(i);
    }
  }
  return first_word;
}

bool CommonsensePriors::forAThing(const std::string& label) const {
  // Known by its head noun only, with a thing before it that is no room and no furnishing
  // ("shoe cabinet": a cabinet for shoes; not "sofa bed"). The encoder reads it as the head
  // (right for matching a "cabinet" goal), but where a cabinet stands is what the table's
  // cabinets say, kitchen ones; a kind made for another thing may stand elsewhere. Animals
  // are the encoder's own ("dog bed").
  const auto sense = wordnet::resolveLabel(label);
  if (!sense) return false;
  for (const auto& m : sense->modifiers) {
    if (roomNamedBy(m) >= 0 || wordnet::namesAnimal(m) || wordnet::furnishes(m)) continue;
    const std::string lex = wordnet::usualNounLexfile(m);
    if (lex == "noun.artifact" || lex == "noun.object" || lex == "noun.food" || lex == "noun.plant" ||
        lex == "noun.substance")
      return true;
  }
  return false;
}

int CommonsensePriors::roomCue(const std::string& label) const {
  // The words before the head noun of the label ("office chair", "kitchen counter") and of the
  // nearest hypernym's first lemma ("microwave" -> "kitchen appliance", "filing cabinet" ->
  // "office furniture", "bed" -> "bedroom furniture", "treadmill" -> "exercise device").
  const auto check = [&](const std::vector<std::string>& tokens) {
    for (size_t i = 0; i + 1 < tokens.size(); ++i)
      if (const int r = roomNamedBy(tokens[i]); r >= 0) return r;
    return -1;
  };
  if (const int r = check(wordnet::labelTokens(label)); r >= 0) return r;
  const auto hyp = wordnet::hypernymsOf(label);
  return hyp.empty() ? -1 : check(wordnet::labelTokens(hyp.front()));
}

int CommonsensePriors::roomIndex(const std::string& name) const {
  const std::string n = lower(trim(name));
  for (size_t i = 0; i < rooms_.size(); ++i) {
    if (lower(rooms_[i].name) == n) return int(i);
    for (const auto& a : rooms_[i].aliases)
      if (lower(a) == n) return int(i);
  }
  if (!encoder_ || n.empty()) return -1;
  int best = -1;
  double best_c = match_cosine_;
  for (size_t i = 0; i < rooms_.size(); ++i) {
    const double c = encoder_->similarity(n, rooms_[i].name);
    if (c >= best_c) best_c = c, best = int(i);
  }
  return best;
}

const CommonsensePriors::StateRow* CommonsensePriors::stateFor(const std::string& word) const {
  const auto asAdjective = [&](const std::string& a) -> const StateRow* {
    if (const auto it = states_.find(a); it != states_.end()) return &it->second;
    for (const auto& sense : wordnet::adjectiveClustersOf(a, 2))
      for (const auto& w : sense)
        if (const auto it = states_.find(w); it != states_.end()) return &it->second;
    return nullptr;
  };
  if (const StateRow* row = asAdjective(word)) return row;
  // A participle no row or cluster holds, of a verb one of whose senses is being in a state:
  // "starving" (to starve: "be hungry; go without food"), "freezing" (its third sense, "be
  // cold"), "baking" (its fourth, "be very hot"). The adjective after "be" and words of degree.
  const bool participle = (word.size() > 4 && word.compare(word.size() - 3, 3, "ing") == 0) ||
                          (word.size() > 3 && word.compare(word.size() - 2, 2, "ed") == 0);
  if (!participle) return nullptr;
  for (const auto& gloss : wordnet::verbGlossesOf(word, kStateVerbSenses)) {
    std::istringstream in(gloss);
    std::string w;
    if (!(in >> w) || w != "be") continue;
    while (in >> w && request::degreeWords().count(w)) {
    }
    while (!w.empty() && !std::isalpha(static_cast<unsigned char>(w.back()))) w.pop_back();
    if (w.empty()) continue;
    if (const StateRow* row = asAdjective(w)) return row;
  }
  return nullptr;
}

std::vector<double> CommonsensePriors::roomsGivenObject(const std::string& label) const {
  const std::string key = lower(trim(label));
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (auto it = cache_.find(key); it != cache_.end()) return it->second;
  }
  std::vector<double> sum(rooms_.size(), 0.0);
  int n = 0;
  // Exact category words (or aliases) first: the label's own, else the category Matterport3D's
  // annotators filed it under ("nightstand" -> chest of drawers), else those of a WordNet synonym
  // of it ("tv" -> "television", an alias of tv_monitor). A label that names a category is not
  // widened by its synonyms: "toilet" is also a "stool" and a "pot" in WordNet, which put a
  // kitchen's pots into every bathroom. Otherwise every row within match_cosine.
  // A row, or a loose match's: half of it, mixed with a uniform row.
  auto addRow = [&](const Row& r, bool loose) {
    for (size_t k = 0; k < sum.size(); ++k) sum[k] += loose ? 0.5 * r.p[k] + 0.5 / double(sum.size()) : r.p[k];
    ++n;
  };
  auto addNamed = [&](const std::vector<std::string>& keys, bool loose) {
    for (const Row& r : rows_)
      if (std::any_of(keys.begin(), keys.end(), [&](const std::string& k) {
            return std::any_of(r.names.begin(), r.names.end(), [&](const std::string& x) { return joined(x) == joined(k); });
          }))
        addRow(r, loose);
  };
  addNamed({key}, false);
  if (n == 0)
    if (auto it = mp3d_.find(key); it != mp3d_.end()) addNamed({it->second}, false);
  if (n == 0) {
    std::vector<std::string> synonyms;
    for (const auto& syn : wordnet::synonymsOf(key)) synonyms.push_back(lower(syn));
    // Synonyms of a label known by its head noun are the head's: a "shoe cabinet" is matched
    // as any cabinet, whose row is the table's (kitchen) cabinets. Made for another thing, it
    // matches loosely.
    addNamed(synonyms, forAThing(key));
  }
  // Rows of compounds the label is the modifier of are its accessories, which stand where it
  // does: "tv" -> TVStand, "toilet" -> ToiletPaper, "shower" -> ShowerCurtain. (MP3D files a
  // tv and an office's computer monitor alike under tv_monitor, whose row leans to offices.)
  // The label's WordNet synonyms name the same thing: "television" -> "tv" -> TVStand.
  const bool matched = n > 0;
  if (matched) {
    // Category words are space-separated tokens: an accessory is "<name> <one word>".
    std::vector<std::string> names{categoryWords(key)};
    for (const auto& syn : wordnet::synonymsOf(key)) names.push_back(categoryWords(syn));
    for (const Row& r : rows_)
      if (std::any_of(names.begin(), names.end(), [&](const std::string& w) {
            return !w.empty() && r.category.size() > w.size() + 1 && r.category.compare(0, w.size() + 1, w + " ") == 0 &&
                   r.category.find(' ', w.size() + 1) == std::string::npos;
          }))
        addRow(r, false);
  }
  // A room named in the label or in its nearest hypernym is the label's own word for where it
  // stands ("office chair": a chair, and an office's): one more row, all on that room. It stands
  // in for the loose text match when no category matched.
  const int cue = roomCue(key);
  if (cue >= 0) {
    sum[size_t(cue)] += 1.0;
    ++n;
  }
  if (!matched && encoder_) {
    // Every category within match_cosine; failing that, the nearest one(s) within
    // kNearCosine ("refrigerator" -> Fridge, "nightstand" -> side table), at half weight
    // (mixed with a uniform row) since the match is loose.
    const Embedding e = encoder_->encode(key);
    std::vector<double> cos(rows_.size());
    double best = 0.0;
    // A row made for another thing is near a label through its head noun only when the label
    // is that head, or that kind: a "computer" or an "x-ray machine" is no coffee machine
    // (0.76 and 0.89 by the encoder), and neither is a kitchen's; a "sponge" is near a dish
    // sponge, but loosely, as above: it need not be one.
    const auto tokens = wordnet::labelTokens(key);
    const auto forms = tokens.empty() ? std::vector<std::string>{} : wordnet::nounForms(tokens.back());
    const auto namesKind = [&](const std::string& name, const std::string& head) {
      if (tokens.empty()) return false;
      if (tokens.back() != head && std::find(forms.begin(), forms.end(), head) == forms.end()) return false;
      const auto words = wordnet::labelTokens(name);
      return std::all_of(tokens.begin(), tokens.end() - 1,
                         [&](const std::string& t) { return std::find(words.begin(), words.end(), t) != words.end(); });
    };
    std::vector<char> kind(rows_.size(), 0);
    for (size_t i = 0; i < rows_.size(); ++i) {
      cos[i] = 0.0;
      for (size_t j = 0; j < rows_[i].names.size(); ++j) {
        const std::string& head = rows_[i].kind_heads[j];
        if (!head.empty() && !namesKind(rows_[i].names[j], head)) continue;
        const double c = cosineSimilarity(e, encoder_->encode(rows_[i].names[j]));
        if (c > cos[i]) cos[i] = c, kind[i] = !head.empty();
      }
      best = std::max(best, cos[i]);
    }
    const bool loose = best < match_cosine_ || forAThing(key);
    if (!loose || (best >= kNearCosine && cue < 0))
      for (size_t i = 0; i < rows_.size(); ++i)
        if (cos[i] >= (loose ? best - 1e-9 : match_cosine_)) addRow(rows_[i], loose || kind[i]);
  }
  std::vector<double> out;
  if (n > 0) {
    out = sum;
    normalise(out);
  }
  std::lock_guard<std::mutex> lock(mutex_);
  cache_[key] = out;
  return out;
}

double CommonsensePriors::adjacency(int a, int b) const {
  if (a < 0 || b < 0 || size_t(a) >= rooms_.size() || size_t(b) >= rooms_.size()) return 0.0;
  return adjacency_[size_t(a)][size_t(b)];
}

}  // namespace ussnav
