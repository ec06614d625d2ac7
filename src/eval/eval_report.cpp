#include "ussnav/eval/eval_report.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "ussnav/eval/metrics.hpp"

namespace ussnav {

namespace {

std::string clean(std::string s) {
  for (char& c : s)
    if (c == ',' || c == '\n' || c == '\r' || c == '"') c = ' ';
  return s;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : line) {
    if (c == ',') out.push_back(cur), cur.clear();
    else cur += c;
  }
  out.push_back(cur);
  return out;
}

constexpr int kColumns = 24;
constexpr int kColumnsSighting = 21;  // episodes.csv before the region columns
constexpr int kColumnsLabels = 18;  // episodes.csv before the sighting columns
constexpr int kColumnsBefore = 16;  // episodes.csv before the region-label columns
const char* const kHeaderBefore =
    "world,goal,planner,seed,split,success,spl,path_length_m,shortest_path_m,time_s,frames,collisions,end_reason,"
    "found_label,update_hz,wall_s";
const char* const kHeaderLabels =
    "world,goal,planner,seed,split,success,spl,path_length_m,shortest_path_m,time_s,frames,collisions,end_reason,"
    "found_label,update_hz,wall_s,labels_scored,labels_correct";
const char* const kHeaderSighting =
    "world,goal,planner,seed,split,success,spl,path_length_m,shortest_path_m,time_s,frames,collisions,end_reason,"
    "found_label,update_hz,wall_s,labels_scored,labels_correct,search_m,approach_shortest_m,view_shortest_m";

// A CSV field that is a number and nothing else ("0.8x" is not 0.8, as std::stod would read it).
template <typename T>
T whole(const std::string& s) {
  T v{};
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) throw std::invalid_argument("number");
  return v;
}

}  // namespace

std::string EpisodeRow::key() const { return world + "|" + goal + "|" + planner + "|" + std::to_string(seed); }

EpisodeRow rowOf(const EpisodeResult& r) {
  EpisodeRow w;
  w.world = r.world, w.goal = r.goal, w.planner = r.planner, w.seed = r.seed;
  w.split = r.multi_room ? "multi_room" : "single_room";
  w.success = r.success, w.spl = r.spl, w.path_length_m = r.path_length_m, w.shortest_path_m = r.shortest_path_m;
  w.time_s = r.time_s, w.frames = r.frames, w.collisions = r.collisions, w.end_reason = r.end_reason;
  w.found_label = r.found_object ? r.found_object->label : "";
  w.update_hz = r.update_hz, w.wall_s = r.wall_s;
  w.labels_scored = r.labels_scored, w.labels_correct = r.labels_correct;
  w.search_m = r.search_m, w.approach_shortest_m = r.approach_shortest_m, w.view_shortest_m = r.view_shortest_m;
  w.region_count = r.region_count, w.region_largest_share = r.region_largest_share, w.region_ari = r.region_ari;
  return w;
}

std::string csvHeader() {
  return "world,goal,planner,seed,split,success,spl,path_length_m,shortest_path_m,time_s,frames,collisions,end_reason,"
         "found_label,update_hz,wall_s,labels_scored,labels_correct,search_m,approach_shortest_m,"
         "view_shortest_m,region_count,region_largest_share,region_ari";
}

std::string toCsv(const EpisodeRow& r) {
  char buf[640];
  std::snprintf(buf, sizeof buf,
                "%s,%s,%s,%llu,%s,%d,%.4f,%.3f,%.3f,%.2f,%d,%d,%s,%s,%.1f,%.2f,%d,%d,%.3f,%.3f,%.3f,%d,%.4f,%.4f",
                clean(r.world).c_str(), clean(r.goal).c_str(), clean(r.planner).c_str(),
                static_cast<unsigned long long>(r.seed), r.split.c_str(), int(r.success), r.spl, r.path_length_m,
                r.shortest_path_m, r.time_s, r.frames, r.collisions, clean(r.end_reason).c_str(),
                clean(r.found_label).c_str(), r.update_hz, r.wall_s, r.labels_scored, r.labels_correct, r.search_m,
                r.approach_shortest_m, r.view_shortest_m, r.region_count, r.region_largest_share, r.region_ari);
  return buf;
}

std::vector<EpisodeRow> readEpisodesCsv(const std::filesystem::path& path, int* bad) {
  std::vector<EpisodeRow> rows;
  if (bad) *bad = 0;
  std::ifstream in(path);
  if (!in) return rows;
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();  // written on Windows
    if (header) {
      header = false;
      if (line == csvHeader() || line == kHeaderBefore || line == kHeaderLabels || line == kHeaderSighting) continue;
    }
    const auto f = split(line);
    try {
      if (int(f.size()) != kColumns && int(f.size()) != kColumnsSighting && int(f.size()) != kColumnsLabels &&
          int(f.size()) != kColumnsBefore)
        throw std::invalid_argument("columns");
      EpisodeRow r;
      r.world = f[0], r.goal = f[1], r.planner = f[2], r.seed = whole<unsigned long long>(f[3]), r.split = f[4];
      if (r.split != "single_room" && r.split != "multi_room") throw std::invalid_argument("split");
      r.success = whole<int>(f[5]) != 0, r.spl = whole<double>(f[6]), r.path_length_m = whole<double>(f[7]);
      r.shortest_path_m = whole<double>(f[8]), r.time_s = whole<double>(f[9]), r.frames = whole<int>(f[10]);
      r.collisions = whole<int>(f[11]), r.end_reason = f[12], r.found_label = f[13], r.update_hz = whole<double>(f[14]);
      r.wall_s = whole<double>(f[15]);
      if (int(f.size()) >= kColumnsLabels) r.labels_scored = whole<int>(f[16]), r.labels_correct = whole<int>(f[17]);
      if (int(f.size()) >= kColumnsSighting)
        r.search_m = whole<double>(f[18]), r.approach_shortest_m = whole<double>(f[19]), r.view_shortest_m = whole<double>(f[20]);
      if (int(f.size()) >= kColumns)
        r.region_count = whole<int>(f[21]), r.region_largest_share = whole<double>(f[22]), r.region_ari = whole<double>(f[23]);
      rows.push_back(r);
    } catch (const std::exception&) {
      if (bad) ++*bad;
    }
  }
  return rows;
}

std::vector<std::string> splitsOf(const EpisodeRow& r) {
  std::vector<std::string> s = {r.split};
  if (r.split == "multi_room" && r.shortest_path_m >= kLongHorizonM) s.push_back("long_horizon");
  s.push_back("all");
  return s;
}

namespace {

constexpr std::array<const char*, 4> kSplits = {"all", "single_room", "multi_room", "long_horizon"};
constexpr double kSameSpl = 0.02;  // paired episodes closer than this count as the same

std::string pairKey(const EpisodeRow& r) { return r.world + "|" + r.goal + "|" + std::to_string(r.seed); }

bool in(const EpisodeRow& r, const std::string& split) {
  const auto s = splitsOf(r);
  return std::find(s.begin(), s.end(), split) != s.end();
}

// Every other planner against `frontier`, pairing rows of the same world, goal and seed.
void pairedMarkdown(const std::vector<EpisodeRow>& rows, std::ostringstream& md) {
  const std::string base = "frontier";
  std::map<std::string, const EpisodeRow*> baseline;
  std::set<std::string> others;
  for (const EpisodeRow& r : rows) {
    if (r.planner == base) baseline[pairKey(r)] = &r;
    else others.insert(r.planner);
  }
  if (baseline.empty()) return;
  for (const std::string& planner : others) {
    md << "## " << planner << " against " << base << ", episode by episode\n\n"
       << "| split | pairs | SPL " << base << " | SPL " << planner << " | ratio | better | same | worse |\n"
       << "|---|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const char* split : kSplits) {
      int n = 0, better = 0, worse = 0;
      double a = 0, b = 0;
      for (const EpisodeRow& r : rows) {
        if (r.planner != planner || !in(r, split)) continue;
        const auto it = baseline.find(pairKey(r));
        if (it == baseline.end()) continue;
        ++n, a += it->second->spl, b += r.spl;
        if (r.spl > it->second->spl + kSameSpl) ++better;
        else if (r.spl < it->second->spl - kSameSpl) ++worse;
      }
      char ratio[32] = "-", mean_a[32] = "-", mean_b[32] = "-", line[256];  // no pairs: "-", not 0
      if (a > 0) std::snprintf(ratio, sizeof ratio, "%.2fx", b / a);
      if (n > 0) {
        std::snprintf(mean_a, sizeof mean_a, "%.3f", a / n);
        std::snprintf(mean_b, sizeof mean_b, "%.3f", b / n);
      }
      std::snprintf(line, sizeof line, "| %s | %d | %s | %s | %s | %d | %d | %d |\n", split, n, mean_a, mean_b, ratio,
                    better, n - better - worse, worse);
      md << line;
    }
    md << "\n";
  }
}

// Where the path goes: successful episodes whose goal was sighted (search_m >= 0 and a
// reachable success pose from there), per planner and split, mean path until the sighting and
// after it, and L* from the sighting.
nlohmann::json pathSplitJson(const std::vector<EpisodeRow>& rows, const std::string& planner, const std::string& split) {
  int n = 0;
  double path = 0, search = 0, approach = 0, approach_star = 0, star = 0, view_star = 0;
  for (const EpisodeRow& r : rows) {
    if (r.planner != planner || !in(r, split) || !r.success || r.search_m < 0 || r.approach_shortest_m < 0) continue;
    ++n, path += r.path_length_m, search += r.search_m, star += std::max(r.shortest_path_m, 0.0);
    approach += std::max(0.0, r.path_length_m - r.search_m), approach_star += r.approach_shortest_m;
    view_star += std::max(r.view_shortest_m, 0.0);
  }
  const double d = std::max(n, 1);
  return {{"episodes", n},
          {"path_length_m", path / d},
          {"shortest_path_m", star / d},
          {"view_shortest_m", view_star / d},
          {"search_m", search / d},
          {"approach_m", approach / d},
          {"approach_shortest_m", approach_star / d}};
}

}  // namespace

nlohmann::json summaryJson(const std::vector<EpisodeRow>& rows) {
  std::map<std::string, std::map<std::string, std::vector<EpisodeOutcome>>> by;
  std::map<std::string, std::map<std::string, double>> spl_sum;
  for (const EpisodeRow& r : rows) {
    const EpisodeOutcome o{r.success, r.path_length_m, std::max(r.shortest_path_m, 1e-6), r.time_s, r.collisions};
    for (const std::string& split : splitsOf(r)) {
      by[r.planner][split].push_back(o);
      spl_sum[r.planner][split] += r.spl;
    }
  }
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [planner, splits] : by) {
    for (const char* split : kSplits) {
      const auto it = splits.find(split);
      const std::vector<EpisodeOutcome> none;
      const std::vector<EpisodeOutcome>& eps = it == splits.end() ? none : it->second;
      // summarize() recomputes SPL from the lengths; the rows carry the episode's own SPL.
      SplitSummary s = summarize(eps);
      s.spl = eps.empty() ? 0.0 : spl_sum[planner][split] / double(eps.size());
      j[planner][split] = {{"episodes", s.episodes}, {"sr", s.sr}, {"spl", s.spl}, {"path_length_m", s.path_length_m},
                           {"time_s", s.time_s}, {"collisions", s.collisions},
                           {"path_split", pathSplitJson(rows, planner, split)}};
    }
  }
  std::map<std::string, std::pair<int, int>> labels;  // planner -> scored, correct
  for (const EpisodeRow& r : rows) {
    labels[r.planner].first += r.labels_scored;
    labels[r.planner].second += r.labels_correct;
  }
  // The final regions: mean count and largest share over every episode with regions, mean ARI
  // over those whose world has rooms (region_ari >= -1 + 1e-9; -1 marks none).
  std::map<std::string, std::array<double, 5>> reg;  // planner -> episodes, count, share, ari n, ari sum
  for (const EpisodeRow& r : rows) {
    if (r.region_count <= 0) continue;
    auto& a = reg[r.planner];
    a[0] += 1, a[1] += r.region_count, a[2] += r.region_largest_share;
    if (r.region_ari > -1.0 + 1e-9) a[3] += 1, a[4] += r.region_ari;
  }
  for (const auto& [planner, a] : reg) {
    j[planner]["regions"] = {{"episodes", int(a[0])}, {"mean_count", a[1] / a[0]}, {"mean_largest_share", a[2] / a[0]},
                             {"ari_episodes", int(a[3])}};
    if (a[3] > 0) j[planner]["regions"]["mean_ari"] = a[4] / a[3];
  }
  for (const auto& [planner, sc] : labels)
    if (sc.first > 0)
      j[planner]["region_labels"] = {
          {"scored", sc.first}, {"correct", sc.second}, {"accuracy", double(sc.second) / double(sc.first)}};
  return j;
}

std::string summaryMarkdown(const std::vector<EpisodeRow>& rows, const std::string& title) {
  const nlohmann::json j = summaryJson(rows);
  std::ostringstream md;
  md << "# " << title << "\n\n" << rows.size() << " episodes.\n\n";
  for (const char* split : kSplits) {
    md << "## " << split << "\n\n| planner | episodes | SR | SPL | path (m) | time (s) | collisions |\n"
       << "|---|---:|---:|---:|---:|---:|---:|\n";
    for (auto it = j.begin(); it != j.end(); ++it) {
      const auto& s = it.value()[split];
      char line[256];
      std::snprintf(line, sizeof line, "| %s | %d | %.3f | %.3f | %.1f | %.1f | %.2f |\n", it.key().c_str(),
                    s["episodes"].get<int>(), s["sr"].get<double>(), s["spl"].get<double>(),
                    s["path_length_m"].get<double>(), s["time_s"].get<double>(), s["collisions"].get<double>());
      md << line;
    }
    md << "\n";
  }
  bool any_labels = false;
  for (auto it = j.begin(); it != j.end(); ++it) any_labels = any_labels || it.value().contains("region_labels");
  if (any_labels) {
    md << "## region labels\n\n| planner | regions scored | correct | accuracy |\n|---|---:|---:|---:|\n";
    for (auto it = j.begin(); it != j.end(); ++it) {
      if (!it.value().contains("region_labels")) continue;
      const auto& l = it.value()["region_labels"];
      char line[160];
      std::snprintf(line, sizeof line, "| %s | %d | %d | %.3f |\n", it.key().c_str(), l["scored"].get<int>(),
                    l["correct"].get<int>(), l["accuracy"].get<double>());
      md << line;
    }
    md << "\n";
  }
  bool any_regions = false;
  for (auto it = j.begin(); it != j.end(); ++it) any_regions = any_regions || it.value().contains("regions");
  if (any_regions) {
    md << "## regions against the rooms\n\n| planner | episodes | regions | largest holds | episodes in rooms | ARI |\n"
          "|---|---:|---:|---:|---:|---:|\n";
    for (auto it = j.begin(); it != j.end(); ++it) {
      if (!it.value().contains("regions")) continue;
      const auto& g = it.value()["regions"];
      char ari[32] = "-", line[200];
      if (g.contains("mean_ari")) std::snprintf(ari, sizeof ari, "%.3f", g["mean_ari"].get<double>());
      std::snprintf(line, sizeof line, "| %s | %d | %.1f | %.0f %% | %d | %s |\n", it.key().c_str(),
                    g["episodes"].get<int>(), g["mean_count"].get<double>(),
                    100.0 * g["mean_largest_share"].get<double>(), g["ari_episodes"].get<int>(), ari);
      md << line;
    }
    md << "\n";
  }
  pairedMarkdown(rows, md);
  md << "## where the path goes\n\n| split | planner | episodes | path (m) | L* (m) | until sighted (m) | "
        "to a view, shortest (m) | after (m) | after, shortest (m) |\n|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const char* split : kSplits)
    for (auto it = j.begin(); it != j.end(); ++it) {
      const auto& p = it.value()[split]["path_split"];
      if (p["episodes"].get<int>() == 0) continue;
      char line[256];
      std::snprintf(line, sizeof line, "| %s | %s | %d | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f |\n", split,
                    it.key().c_str(), p["episodes"].get<int>(), p["path_length_m"].get<double>(),
                    p["shortest_path_m"].get<double>(), p["search_m"].get<double>(), p["view_shortest_m"].get<double>(),
                    p["approach_m"].get<double>(), p["approach_shortest_m"].get<double>());
      md << line;
    }
  md << "\n";
  md << "SR: success rate; SPL = S * L* / max(L, L*) averaged over episodes (DESIGN.md); single_room: a goal "
        "instance is in the start room; multi_room: none is; long_horizon: multi_room with L* >= "
     << kLongHorizonM << " m; ratio: SPL of the planner over SPL of frontier on the same episodes; same: within "
     << kSameSpl << " SPL; region labels: the final regions' room labels against the room holding most of each "
        "region's nodes (ground truth), over regions whose room type the reasoner can name; where the path goes: "
        "successful episodes whose goal was sighted, the path until the first frame that mapped a goal instance as "
        "the goal (ground truth) and after it, and L* from where the UAV was then; to a view: L* from the start to a "
        "point that sees a goal instance within the detector's range, the least search any planner could do.\n";
  return md.str();
}

}  // namespace ussnav
