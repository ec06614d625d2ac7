#pragma once
// Rows of DIR/episodes.csv (one finished episode each) and the summary tables built from them
// (summary.json: {planner: {split: {episodes, sr, spl, path_length_m, time_s, collisions}}} with
// splits single_room, multi_room, long_horizon, all; summary.md: the same as Markdown tables and,
// where the rows hold `frontier` (the baseline) and another planner, each other planner paired
// with it episode by episode (same world, goal and seed): SPL ratio, better / same / worse; and
// where the path goes: for successful episodes whose goal was sighted, the path until the first
// sighting of a goal instance (search) and after it (approach), against L* from the sighting).
//
// long_horizon is the part of multi_room whose shortest path L* is at least kLongHorizonM: the
// paper's "long-horizon missions", where frontier-only exploration is said to degrade.

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "ussnav/episode/episode.hpp"

namespace ussnav {

struct EpisodeRow {
  std::string world, goal, planner, split, end_reason, found_label;
  uint64_t seed = 1;
  bool success = false;
  double spl = 0, path_length_m = 0, shortest_path_m = -1, time_s = 0, update_hz = 0, wall_s = 0;
  int frames = 0, collisions = 0;
  int labels_scored = 0, labels_correct = 0;  // region labels against ground truth (EpisodeResult)
  // The path split at the goal's first sighting, and L* to a view of the goal (EpisodeResult).
  double search_m = -1, approach_shortest_m = -1, view_shortest_m = -1;
  // The final regions against the world's rooms (EpisodeResult); 0 / 0 / -1 in older files.
  int region_count = 0;
  double region_largest_share = 0, region_ari = -1;
  std::string key() const;  // world|goal|planner|seed
};

constexpr double kLongHorizonM = 15.0;
// The splits a row counts in: its own (single_room or multi_room), long_horizon where it
// qualifies, and all.
std::vector<std::string> splitsOf(const EpisodeRow& r);

EpisodeRow rowOf(const EpisodeResult& r);
std::string csvHeader();
std::string toCsv(const EpisodeRow& r);
// Reads the rows of an episodes.csv; lines that do not parse (an interrupted write) are
// skipped and counted in *bad. A missing file gives no rows.
std::vector<EpisodeRow> readEpisodesCsv(const std::filesystem::path& path, int* bad = nullptr);

// {planner: {split: {episodes, sr, spl, ...}, region_labels: {scored, correct, accuracy}}};
// region_labels only for planners that label regions (labels_scored > 0 somewhere); regions:
// {episodes, mean_count, mean_largest_share, ari_episodes, mean_ari (when ari_episodes > 0)}
// over the episodes with regions (files written before these columns have none).
nlohmann::json summaryJson(const std::vector<EpisodeRow>& rows);
std::string summaryMarkdown(const std::vector<EpisodeRow>& rows, const std::string& title);

}  // namespace ussnav
