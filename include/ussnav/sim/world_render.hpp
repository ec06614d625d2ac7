#pragma once
// Top-down picture of a world: rooms filled by type and labelled, walls black with their
// openings cut out, doors magenta, objects as labelled oriented-box outlines, the start pose,
// a scale bar, and obstacle voxels (scanned worlds) as a max-height projection. Cost: linear
// in rooms + objects + voxels; a 40 x 25 m floor at 30 px/m draws in a few milliseconds.

#include <string>

#include "ussnav/core/image.hpp"
#include "ussnav/sim/world.hpp"

namespace ussnav {

struct RenderOptions {
  double px_per_m = 30.0;     // legible labels from about 25 px/m
  bool object_labels = true;  // category names on objects (skipped where they would collide)
  int max_px = 6000;          // longest image side; px_per_m shrinks to fit
};

Image renderWorld(const World& world, const RenderOptions& options = {});

// Fill colour of a room type in pictures (fixed for known types, a stable pastel otherwise).
Rgb roomTypeColor(const std::string& type);

}  // namespace ussnav
