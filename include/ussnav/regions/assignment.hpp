#pragma once
// Optimal assignment (Hungarian method, shortest augmenting paths with potentials) that
// maximises the total score of a rectangular rows x cols matrix. Used to give new communities
// the ids of the old regions they overlap most. Cost: O(min^2 * max) time, O(rows * cols) memory.

#include <vector>

namespace ussnav {

// result[r] = column assigned to row r, or -1. Every row gets a column while columns last
// (so zero-score pairs may be assigned; callers that need a positive score check it).
// All rows must have the same length. Scores must be finite.
std::vector<int> maxScoreAssignment(const std::vector<std::vector<double>>& score);

}  // namespace ussnav
