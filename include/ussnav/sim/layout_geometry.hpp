#pragma once
// Pure 2-D geometry for floor plans: oriented-box footprints, box overlap (separating axes),
// box-in-polygon containment and point-to-polygon distances. Used by the floor-plan generator,
// world statistics and tests. All functions are O(corners x edges); no allocation beyond the
// returned corner arrays.

#include <array>
#include <utility>
#include <vector>

#include "ussnav/sim/world.hpp"

namespace ussnav {

// The four footprint corners of a box in x-y, counter-clockwise.
std::array<Vec2, 4> footprintCorners(const OrientedBox& b);

// Whether the footprints of two boxes come closer than `gap` (SAT on the four edge normals;
// gap 0 = interiors intersect). Touching footprints do not overlap.
bool footprintsOverlap(const OrientedBox& a, const OrientedBox& b, double gap = 0.0);

// Whether two boxes share volume: footprints come closer than `gap` (x-y only) and z ranges
// intersect by more than 1e-6. A box standing exactly on top of another does not overlap it.
bool boxesOverlap(const OrientedBox& a, const OrientedBox& b, double gap = 0.0);

// Distance from p to the segment [a, b].
double pointSegmentDistance(const Vec2& p, const Vec2& a, const Vec2& b);

// Distance from p to the polygon's boundary (inside or outside alike).
double distanceToBoundary(const Vec2& p, const std::vector<Vec2>& poly);

// Whether the box footprint lies inside `poly` with at least `margin` between every footprint
// corner and the boundary, and no polygon vertex pokes into the footprint (non-convex rooms).
bool footprintInsidePolygon(const OrientedBox& b, const std::vector<Vec2>& poly, double margin = 0.0);

// Distance from p to the box footprint (0 inside).
double distanceToFootprint(const Vec2& p, const OrientedBox& b);

// The solid runs of a wall, as [start, end] metres along it from `a`, once the openings that
// `cut` accepts are taken out (sorted, clamped to the wall, merged where they overlap). A wall
// shorter than 1e-9 m has none. O(openings log openings).
std::vector<std::pair<double, double>> solidRuns(const Wall& w, bool (*cut)(const Opening&));
// The `cut` for every opening, and for doors only (an opening reaching below 0.3 m).
inline bool anyOpening(const Opening&) { return true; }
inline bool doorOpening(const Opening& o) { return o.bottom < 0.3; }

}  // namespace ussnav
