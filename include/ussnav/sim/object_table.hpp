#pragma once
// The object table: every category the generator can place, with a realistic box size and
// placement mode, and per-room-type rules (likelihood, count). docs/object-table.md is this
// table printed by objectTableMarkdown() (a test keeps them equal). Static data; lookups are
// linear over ~45 categories and ~130 rules.

#include <string>
#include <vector>

#include "ussnav/core/types.hpp"

namespace ussnav {

enum class Placement {
  Wall,     // back against a wall, front (+y of the box) into the room
  Corner,   // against a wall, at one end of it
  Center,   // near the middle of the room, long side along the room's long axis
  Free,     // anywhere, axis-aligned with some yaw jitter
  OnTop,    // on the top face of a parent object
  Around,   // beside a parent (chairs around a table), facing it
  Front,    // in front of a parent (office chair at a desk), facing it
  Mounted,  // on a wall, bottom at mount_z (whiteboard, mirror)
};

struct ObjectCategory {
  std::string name;                  // lower case, spaces allowed ("office chair")
  Vec3 size;                         // width (along the wall), depth, height; metres
  Placement placement = Placement::Wall;
  std::vector<std::string> parents;  // OnTop / Around / Front: categories it goes with
  double mount_z = 0.0;              // Mounted: height of the bottom edge above the floor
  double yaw_jitter_deg = 0.0;       // Free: random turn added to the axis-aligned yaw
};

struct PlacementRule {
  std::string style;      // "" = every style, else "office" or "apartment"
  std::string room_type;
  std::string category;
  double probability = 1.0;  // chance the room gets the category at all (per parent if per_parent)
  int min_count = 1, max_count = 1;
  double m2_per_extra = 0.0;  // > 0: max_count grows to floor(room area / m2_per_extra)
  bool per_parent = false;    // count is per parent object already in the room
};

const std::vector<ObjectCategory>& objectCategories();
const ObjectCategory* findCategory(const std::string& name);  // nullptr if unknown
const std::vector<PlacementRule>& placementRules();
// Rules that apply to a room of `room_type` in a world of `style`, in placement order
// (parents before the objects that go with them).
std::vector<PlacementRule> rulesFor(const std::string& style, const std::string& room_type);
const char* placementName(Placement p);

// The table as Markdown (the body of docs/object-table.md).
std::string objectTableMarkdown();

}  // namespace ussnav
