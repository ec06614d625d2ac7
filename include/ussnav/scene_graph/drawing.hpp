#pragma once
// Top-down pictures of a SceneGraph document: regions as the convex hull of their nodes'
// centres filled in a palette colour with their id, edges coloured by type, node centres, and
// objects as labelled dots. Works on a loaded document, no live modules needed.
// Cost: O(nodes + edges + objects + region hulls n log n).

#include "ussnav/core/image.hpp"
#include "ussnav/scene_graph/scene_graph.hpp"

namespace ussnav {

struct SceneDrawOptions {
  bool regions = true;
  double region_alpha = 0.28;
  bool edges = true;
  bool nodes = true;
  bool objects = true;
  bool coverage = false;    // visited coverage cells, light grey
};

void drawRegions(Image& img, const TopDownView& view, const SceneGraph& g, double alpha = 0.28);
void drawSceneGraph(Image& img, const TopDownView& view, const SceneGraph& g, const SceneDrawOptions& opt = {});
// x-y bounds of everything in the document (node hulls, objects, visited cells).
Aabb sceneBounds(const SceneGraph& g);

}  // namespace ussnav
