#pragma once
// DIR/index.html of `ussnav eval`: one self-contained page (no network) with the summary table
// (SR and SPL per planner and split) and every episode as a row: world, goal, planner, seed,
// split, result, SPL, path, L*, time, region labels; columns sort on a click, a box filters the
// rows, and where the episode's folder was saved (--save-episodes) the row links its scene-graph
// page and top-down picture. Cost: O(rows).

#include <string>
#include <vector>

#include "ussnav/eval/eval_report.hpp"

namespace ussnav {

// The folder of an episode under DIR/episodes/ (`--save-episodes`): world_goal_planner_sSEED,
// the goal's characters other than letters, digits, '-' and '.' written as '_'.
std::string episodeFolderName(const EpisodeRow& r);

// The page; `saved` tells whether each row's folder exists (same order as `rows`).
std::string evalIndexHtml(const std::vector<EpisodeRow>& rows, const std::vector<bool>& saved, const std::string& title);

}  // namespace ussnav
