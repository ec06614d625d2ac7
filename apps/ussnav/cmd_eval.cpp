// `ussnav eval`: many episodes (suite worlds x goals x seeds x planners), in parallel, resumable:
// every finished episode is appended to DIR/episodes.csv at once, and a re-run skips the
// episodes already there. Ends by writing DIR/summary.json and DIR/summary.md (eval_report.hpp)
// and DIR/index.html (eval_index.hpp).

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>

#include "command.hpp"
#include "ussnav/core/error.hpp"
#include "ussnav/core/io.hpp"
#include "ussnav/core/timing.hpp"
#include "ussnav/episode/goal.hpp"
#include "ussnav/eval/eval_index.hpp"
#include "ussnav/eval/eval_report.hpp"
#include "ussnav/eval/suite.hpp"
#include "ussnav/perception/text_encoder.hpp"
#include "ussnav/reasoning/instruction.hpp"

namespace ussnav::cli {
namespace {

struct EvalArgs {
  std::string suite = "configs/suites/default.yaml", planners = "frontier,full", out = "out/eval";
  std::string reasoner;
  int jobs = 0;
  bool fresh = false, save_episodes = false;
};

std::vector<std::string> splitList(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

struct Job {
  size_t world;
  std::string goal, planner;
  uint64_t seed;
};

void runEval(const EvalArgs& a) {
  const Config& cfg0 = globals().config();
  const Suite suite = loadSuite(a.suite);
  Config cfg = cfg0;
  if (suite.max_time_s) cfg.episode.max_time_s = *suite.max_time_s;
  if (!a.reasoner.empty()) cfg.reasoning.reasoner = a.reasoner;
  const std::vector<std::string> planners = splitList(a.planners);
  if (planners.empty()) throw InputError("--planners", "planners", "expected a comma-separated list, e.g. frontier,full");
  for (const auto& p : planners) makePlanner(p);  // unknown names fail here

  // Worlds, and the goals each holds (a goal without an instance is skipped).
  std::vector<World> worlds;
  const std::shared_ptr<const TextEncoder> encoder(makeTextEncoder(cfg.perception));
  const auto priors = CommonsensePriors::load(CommonsensePriors::defaultDir(), encoder);
  std::vector<Job> jobs;
  int skipped = 0;
  for (size_t i = 0; i < suite.worlds.size(); ++i) {
    progress("eval: preparing world " + suite.worlds[i].name);
    worlds.push_back(materializeWorld(suite.worlds[i]));
    const auto& goals = suite.worlds[i].goals.empty() ? suite.goals : suite.worlds[i].goals;
    for (const std::string& goal : goals) {
      const Instruction ins = interpretInstruction(goal, *priors);
      if (ins.targets.empty()) throw InputError(a.suite, "goals", "'" + goal + "' names no object to find");
      const GoalMatcher m = instructionGoal(ins, encoder, cfg.episode.goal_similarity);
      if (goalInstances(worlds.back(), m).empty()) {
        ++skipped;
        continue;
      }
      for (uint64_t seed : suite.seeds)
        for (const std::string& p : planners) jobs.push_back({i, goal, p, seed});
    }
  }
  progressDone();

  const std::filesystem::path out(a.out);
  std::filesystem::create_directories(out);
  const std::filesystem::path csv = out / "episodes.csv";
  if (a.fresh) std::filesystem::remove(csv);
  // The reasoner changes `full` episodes: refuse to resume rows made with another one.
  const std::filesystem::path run_json = out / "run.json";
  if (std::filesystem::exists(csv) && std::filesystem::exists(run_json)) {
    const nlohmann::json prev = readJsonFile(run_json);
    if (prev.value("reasoner", "") != cfg.reasoning.reasoner)
      throw InputError(run_json.string(), "reasoner",
                       "episodes in this folder used the '" + prev.value("reasoner", "") + "' reasoner, not '" +
                           cfg.reasoning.reasoner + "'; pass --fresh or another --out");
  }
  writeJsonAtomic(run_json, {{"suite", a.suite}, {"reasoner", cfg.reasoning.reasoner}});
  int bad = 0;
  std::vector<EpisodeRow> rows = readEpisodesCsv(csv, &bad);
  std::set<std::string> done;
  for (const auto& r : rows) done.insert(r.key());
  {  // Rewrite the file clean (drops a line cut by an interruption).
    std::string text = csvHeader() + "\n";
    for (const auto& r : rows) text += toCsv(r) + "\n";
    writeFileAtomic(csv, text);
  }
  std::vector<Job> todo;
  for (const Job& j : jobs) {
    EpisodeRow k;
    k.world = suite.worlds[j.world].name, k.goal = j.goal, k.planner = j.planner, k.seed = j.seed;
    if (!done.count(k.key())) todo.push_back(j);
  }
  std::printf("eval %s: %zu worlds, %zu episodes (%d world/goal pairs skipped: no instance), %zu already done%s\n",
              suite.name.c_str(), worlds.size(), jobs.size(), skipped, jobs.size() - todo.size(),
              bad ? (", " + std::to_string(bad) + " unreadable rows dropped").c_str() : "");
  std::fflush(stdout);

  const int n_jobs = std::max(1, a.jobs > 0 ? a.jobs : int(std::min(2u, std::max(1u, std::thread::hardware_concurrency()))));
  std::atomic<size_t> next{0};
  std::atomic<int> finished{0};
  std::mutex mu;
  std::ofstream csv_out(csv, std::ios::app);
  const Stopwatch wall;
  std::string first_error;
  auto worker = [&] {
    while (true) {
      const size_t i = next.fetch_add(1);
      if (i >= todo.size()) return;
      const Job& j = todo[i];
      EpisodeSpec spec;
      spec.world = worlds[j.world];
      spec.world_name = suite.worlds[j.world].name;
      spec.goal = j.goal;
      spec.planner = j.planner;
      spec.seed = j.seed;
      spec.start = suite.worlds[j.world].start;
      try {
        const EpisodeRun run = runEpisode(spec, cfg);
        const EpisodeRow row = rowOf(run.result);
        std::lock_guard<std::mutex> lock(mu);
        if (a.save_episodes)
          writeEpisode((out / "episodes" / episodeFolderName(row)).string(), run);
        csv_out << toCsv(row) << "\n";
        csv_out.flush();
        rows.push_back(row);
        const int k = ++finished;
        const double per = wall.ms() / 1000.0 / k;
        char line[300];
        std::snprintf(line, sizeof line, "eval: %d/%zu  %s %s \"%s\" seed %llu: %s SPL %.2f  (ETA %.0f s)", k, todo.size(),
                      j.planner.c_str(), spec.world_name.c_str(), j.goal.c_str(), static_cast<unsigned long long>(j.seed),
                      row.success ? "found" : row.end_reason.c_str(), row.spl, per * double(todo.size() - size_t(k)) / n_jobs);
        progress(line);
      } catch (const std::exception& e) {
        std::lock_guard<std::mutex> lock(mu);
        if (first_error.empty()) first_error = spec.world_name + " / " + j.goal + ": " + e.what();
        next = todo.size();  // stop handing out work
      }
    }
  };
  std::vector<std::thread> threads;
  for (int t = 0; t < n_jobs; ++t) threads.emplace_back(worker);
  for (auto& t : threads) t.join();
  progressDone();
  csv_out.close();
  if (!first_error.empty()) throw std::runtime_error("episode failed: " + first_error + " (finished episodes are in " + csv.string() + "; re-run to resume)");

  writeJsonAtomic(out / "summary.json", summaryJson(rows));
  const std::string title = "ussnav eval: " + suite.name + " (full: " + cfg.reasoning.reasoner + " reasoner)";
  const std::string md = summaryMarkdown(rows, title);
  writeFileAtomic(out / "summary.md", md);
  std::vector<bool> saved;
  for (const EpisodeRow& r : rows)
    saved.push_back(std::filesystem::exists(out / "episodes" / episodeFolderName(r) / "result.json"));
  writeFileAtomic(out / "index.html", evalIndexHtml(rows, saved, title));
  std::printf("%s", md.c_str());
  std::printf("wall %.0f s with %d jobs; wrote %s/episodes.csv, summary.json, summary.md, index.html (open it in a browser)\n",
              wall.ms() / 1000.0, n_jobs, a.out.c_str());
}

void addEvalCommand(CLI::App& root) {
  static EvalArgs args;
  auto* cmd = root.add_subcommand("eval", "Run a suite of episodes per planner; write episodes.csv, summary.json, summary.md, index.html (resumable)");
  cmd->fallthrough();
  cmd->add_option("--suite", args.suite, "suite YAML (docs/eval.md)")->capture_default_str()->check(CLI::ExistingFile);
  cmd->add_option("--planners", args.planners, "comma-separated: frontier, tsp, full")->capture_default_str();
  cmd->add_option("--out", args.out, "output folder")->capture_default_str();
  cmd->add_option("--reasoner", args.reasoner, "coarse level of `full`: builtin | llm | oracle (ground truth, an upper bound) | oracle-labels (the true room types, the builtin rule); default: reasoning.reasoner")
      ->check(CLI::IsMember({"builtin", "llm", "oracle", "oracle-labels"}));
  cmd->add_option("--jobs", args.jobs, "episodes run in parallel (default: min(2, cores))");
  cmd->add_flag("--fresh", args.fresh, "discard DIR/episodes.csv instead of resuming");
  cmd->add_flag("--save-episodes", args.save_episodes, "also write each episode's result, graph and pictures under DIR/episodes/");
  cmd->callback([] { runEval(args); });
}

}  // namespace
USSNAV_COMMAND(41, addEvalCommand);
}  // namespace ussnav::cli
