#pragma once
// Top-down pictures of the Spatial Connectivity Graph on a core Image: each polyhedron as the
// convex outline of its hull vertices projected to x-y (filled lightly), centres as dots, edges
// coloured by type (kinematic blue, overlap green, visible orange, loop magenta). O(nodes * V log V).

#include <limits>
#include <vector>

#include "ussnav/core/image.hpp"
#include "ussnav/skeleton/connectivity_graph.hpp"

namespace ussnav {

struct GraphDrawOptions {
  bool polyhedra = true;
  double fill_alpha = 0.10;       // 0: outlines only
  bool centers = true;
  bool edges = true;
  int edge_thickness = 1;
  double node_radius_px = 2.5;
  // Only nodes whose centre z lies in this band (and edges between two such nodes).
  double z_min = -std::numeric_limits<double>::infinity();
  double z_max = std::numeric_limits<double>::infinity();
};

Rgb edgeTypeColor(EdgeType t);
// Convex hull of 2-D points, counter-clockwise, no repeated first point (monotone chain).
std::vector<Vec2> convexOutline2d(std::vector<Vec2> pts);
void drawConnectivityGraph(Image& img, const TopDownView& view, const ConnectivityGraph& g,
                           const GraphDrawOptions& opt = {});

}  // namespace ussnav
