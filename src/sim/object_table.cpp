// Object categories and per-room-type rules. Sizes are typical catalogue sizes of furniture
// and appliances (width x depth x height, metres); the generator jitters each by +-8%.

#include "ussnav/sim/object_table.hpp"

#include <iomanip>
#include <sstream>

namespace ussnav {

namespace {

using P = Placement;

ObjectCategory C(const char* name, double w, double d, double h, Placement p,
                 std::vector<std::string> parents = {}, double mount_z = 0.0, double yaw_jitter_deg = 0.0) {
  return {name, Vec3(w, d, h), p, std::move(parents), mount_z, yaw_jitter_deg};
}

PlacementRule R(const char* style, const char* room, const char* category, double probability, int min_count,
                int max_count, double m2_per_extra = 0.0, bool per_parent = false) {
  return {style, room, category, probability, min_count, max_count, m2_per_extra, per_parent};
}

std::vector<ObjectCategory> makeCategories() {
  const std::vector<std::string> tables{"table", "dining table", "conference table", "desk"};
  return {
      // Sleeping
      C("bed", 1.60, 2.05, 0.55, P::Wall),
      C("nightstand", 0.45, 0.40, 0.55, P::Wall),
      C("wardrobe", 1.20, 0.60, 2.00, P::Wall),
      C("dresser", 1.20, 0.50, 0.80, P::Wall),
      // Washing
      C("toilet", 0.40, 0.70, 0.80, P::Wall),
      C("sink", 0.60, 0.45, 0.85, P::Wall),
      C("bathtub", 1.70, 0.75, 0.60, P::Wall),
      C("shower", 0.90, 0.90, 2.00, P::Corner),
      C("washing machine", 0.60, 0.60, 0.85, P::Wall),
      C("mirror", 0.60, 0.04, 0.80, P::Mounted, {}, 1.10),
      // Living
      C("sofa", 2.00, 0.90, 0.85, P::Wall),
      C("armchair", 0.80, 0.80, 0.90, P::Free, {}, 0.0, 30.0),
      C("coffee table", 1.00, 0.60, 0.45, P::Center),
      C("tv stand", 1.50, 0.45, 0.50, P::Wall),
      C("tv", 1.00, 0.20, 0.65, P::OnTop, {"tv stand", "dresser"}),
      C("bookshelf", 0.90, 0.35, 1.90, P::Wall),
      C("lamp", 0.35, 0.35, 1.60, P::Corner),
      C("plant", 0.40, 0.40, 0.90, P::Corner),
      // Tables and seats
      C("dining table", 1.60, 0.90, 0.75, P::Center),
      C("table", 1.20, 0.80, 0.75, P::Free, {}, 0.0, 10.0),
      C("conference table", 2.80, 1.20, 0.75, P::Center),
      C("chair", 0.45, 0.50, 0.90, P::Around, tables),
      // Work
      C("desk", 1.40, 0.70, 0.75, P::Wall),
      C("office chair", 0.60, 0.60, 1.00, P::Front, {"desk"}),
      C("monitor", 0.55, 0.20, 0.45, P::OnTop, {"desk"}),
      C("laptop", 0.35, 0.25, 0.03, P::OnTop, {"desk", "table", "conference table", "coffee table"}),
      C("whiteboard", 1.80, 0.05, 1.20, P::Mounted, {}, 0.90),
      C("filing cabinet", 0.50, 0.60, 1.30, P::Wall),
      C("printer", 0.60, 0.55, 1.00, P::Wall),
      // Storage
      C("cabinet", 0.90, 0.45, 0.90, P::Wall),
      C("shelf", 1.20, 0.50, 2.00, P::Wall),
      C("box", 0.50, 0.40, 0.40, P::Free, {}, 0.0, 20.0),
      C("shoe cabinet", 1.00, 0.35, 1.00, P::Wall),
      C("coat rack", 0.50, 0.50, 1.80, P::Corner),
      // Kitchen
      C("fridge", 0.70, 0.70, 1.80, P::Wall),
      C("stove", 0.60, 0.60, 0.90, P::Wall),
      C("kitchen counter", 1.80, 0.60, 0.90, P::Wall),
      C("dishwasher", 0.60, 0.60, 0.85, P::Wall),
      C("microwave", 0.50, 0.35, 0.30, P::OnTop, {"kitchen counter"}),
      C("coffee machine", 0.30, 0.40, 0.40, P::OnTop, {"kitchen counter"}),
      C("vending machine", 0.90, 0.80, 1.80, P::Wall),
      // Odds and ends
      C("trash can", 0.30, 0.30, 0.50, P::Corner),
      C("fire extinguisher", 0.20, 0.20, 0.60, P::Corner),
  };
}

std::vector<PlacementRule> makeRules() {
  // {style, room type, category, probability, min, max, m2 per extra, per parent}
  return {
      // Offices: one desk per ~9 m^2, each with a chair, most with a monitor.
      R("", "office", "desk", 1.0, 1, 1, 9.0),
      R("", "office", "office chair", 1.0, 1, 1, 0.0, true),
      R("", "office", "monitor", 0.8, 1, 2, 0.0, true),
      R("", "office", "laptop", 0.4, 1, 1, 0.0, true),
      R("", "office", "filing cabinet", 0.5, 1, 2),
      R("", "office", "bookshelf", 0.4, 1, 1),
      R("", "office", "cabinet", 0.25, 1, 1),
      R("", "office", "whiteboard", 0.2, 1, 1),
      R("", "office", "sofa", 0.1, 1, 1),
      R("", "office", "printer", 0.1, 1, 1),
      R("", "office", "chair", 0.3, 1, 2),
      R("", "office", "plant", 0.4, 1, 1),
      R("", "office", "trash can", 0.6, 1, 1),
      // Meeting rooms
      R("", "meeting room", "conference table", 1.0, 1, 1),
      R("", "meeting room", "chair", 1.0, 4, 6, 3.0),
      R("", "meeting room", "whiteboard", 0.9, 1, 1),
      R("", "meeting room", "tv stand", 0.5, 1, 1),
      R("", "meeting room", "tv", 1.0, 1, 1, 0.0, true),
      R("", "meeting room", "laptop", 0.4, 1, 2),
      R("", "meeting room", "cabinet", 0.3, 1, 1),
      R("", "meeting room", "plant", 0.4, 1, 1),
      R("", "meeting room", "trash can", 0.3, 1, 1),
      // Kitchens
      R("", "kitchen", "kitchen counter", 1.0, 1, 2),
      R("", "kitchen", "sink", 0.95, 1, 1),
      R("", "kitchen", "fridge", 1.0, 1, 1),
      R("apartment", "kitchen", "stove", 0.95, 1, 1),
      R("office", "kitchen", "stove", 0.2, 1, 1),
      R("", "kitchen", "dishwasher", 0.5, 1, 1),
      R("office", "kitchen", "vending machine", 0.3, 1, 1),
      R("", "kitchen", "microwave", 0.7, 1, 1),
      R("office", "kitchen", "coffee machine", 0.8, 1, 1),
      R("apartment", "kitchen", "coffee machine", 0.4, 1, 1),
      R("office", "kitchen", "table", 0.8, 1, 2),
      R("apartment", "kitchen", "table", 0.5, 1, 1),
      R("", "kitchen", "chair", 0.9, 2, 4),
      R("", "kitchen", "trash can", 0.8, 1, 1),
      R("", "kitchen", "cabinet", 0.3, 1, 1),
      R("office", "kitchen", "fire extinguisher", 0.3, 1, 1),
      R("", "kitchen", "plant", 0.2, 1, 1),
      // Bathrooms: office washrooms have several toilets, flats a bath or a shower.
      R("office", "bathroom", "toilet", 1.0, 1, 3, 4.0),
      R("apartment", "bathroom", "toilet", 1.0, 1, 1),
      R("office", "bathroom", "sink", 1.0, 1, 2, 6.0),
      R("apartment", "bathroom", "sink", 1.0, 1, 1),
      R("apartment", "bathroom", "bathtub", 0.6, 1, 1),
      R("apartment", "bathroom", "shower", 0.5, 1, 1),
      R("apartment", "bathroom", "washing machine", 0.35, 1, 1),
      R("", "bathroom", "mirror", 0.85, 1, 1),
      R("", "bathroom", "cabinet", 0.25, 1, 1),
      R("", "bathroom", "trash can", 0.5, 1, 1),
      // Storage
      R("", "storage", "shelf", 1.0, 2, 4),
      R("", "storage", "box", 0.9, 2, 6),
      R("", "storage", "filing cabinet", 0.4, 1, 2),
      R("", "storage", "cabinet", 0.4, 1, 1),
      R("office", "storage", "printer", 0.2, 1, 1),
      // Corridors
      R("", "corridor", "plant", 0.5, 1, 2),
      R("", "corridor", "fire extinguisher", 0.6, 1, 2),
      R("", "corridor", "trash can", 0.3, 1, 1),
      R("", "corridor", "printer", 0.2, 1, 1),
      R("", "corridor", "vending machine", 0.15, 1, 1),
      R("", "corridor", "cabinet", 0.15, 1, 1),
      // Living rooms
      R("", "living room", "sofa", 1.0, 1, 1),
      R("", "living room", "tv stand", 0.9, 1, 1),
      R("", "living room", "tv", 1.0, 1, 1, 0.0, true),
      R("", "living room", "coffee table", 0.9, 1, 1),
      R("", "living room", "armchair", 0.7, 1, 2),
      R("", "living room", "bookshelf", 0.5, 1, 2),
      R("", "living room", "table", 0.2, 1, 1),
      R("", "living room", "chair", 0.3, 1, 2),
      R("", "living room", "laptop", 0.2, 1, 1),
      R("", "living room", "cabinet", 0.3, 1, 1),
      R("", "living room", "lamp", 0.6, 1, 1),
      R("", "living room", "plant", 0.7, 1, 2),
      // Bedrooms
      R("", "bedroom", "bed", 1.0, 1, 1),
      R("", "bedroom", "nightstand", 0.9, 1, 2),
      R("", "bedroom", "wardrobe", 0.9, 1, 1),
      R("", "bedroom", "dresser", 0.5, 1, 1),
      R("", "bedroom", "tv", 0.3, 1, 1, 0.0, true),
      R("", "bedroom", "desk", 0.25, 1, 1),
      R("", "bedroom", "office chair", 1.0, 1, 1, 0.0, true),
      R("", "bedroom", "laptop", 0.4, 1, 1, 0.0, true),
      R("", "bedroom", "lamp", 0.3, 1, 1),
      R("", "bedroom", "plant", 0.25, 1, 1),
      R("", "bedroom", "trash can", 0.2, 1, 1),
      // Hallways
      R("", "hallway", "coat rack", 0.6, 1, 1),
      R("", "hallway", "shoe cabinet", 0.6, 1, 1),
      R("", "hallway", "mirror", 0.4, 1, 1),
      R("", "hallway", "plant", 0.3, 1, 1),
      R("", "hallway", "cabinet", 0.2, 1, 1),
      // Dining rooms
      R("", "dining room", "dining table", 1.0, 1, 1),
      R("", "dining room", "chair", 1.0, 4, 6),
      R("", "dining room", "cabinet", 0.6, 1, 1),
      R("", "dining room", "plant", 0.4, 1, 1),
      R("", "dining room", "lamp", 0.2, 1, 1),
      // Studies
      R("", "study", "desk", 1.0, 1, 1),
      R("", "study", "office chair", 1.0, 1, 1, 0.0, true),
      R("", "study", "monitor", 0.5, 1, 1, 0.0, true),
      R("", "study", "laptop", 0.6, 1, 1, 0.0, true),
      R("", "study", "bookshelf", 0.9, 1, 2),
      R("", "study", "filing cabinet", 0.3, 1, 1),
      R("", "study", "armchair", 0.3, 1, 1),
      R("", "study", "lamp", 0.4, 1, 1),
      R("", "study", "plant", 0.3, 1, 1),
      R("", "study", "trash can", 0.3, 1, 1),
      // Laundry rooms
      R("", "laundry room", "washing machine", 1.0, 1, 2),
      R("", "laundry room", "sink", 0.5, 1, 1),
      R("", "laundry room", "cabinet", 0.6, 1, 1),
      R("", "laundry room", "shelf", 0.4, 1, 1),
      R("", "laundry room", "box", 0.3, 1, 2),
  };
}

}  // namespace

const std::vector<ObjectCategory>& objectCategories() {
  static const std::vector<ObjectCategory> c = makeCategories();
  return c;
}

const ObjectCategory* findCategory(const std::string& name) {
  for (const auto& c : objectCategories())
    if (c.name == name) return &c;
  return nullptr;
}

const std::vector<PlacementRule>& placementRules() {
  static const std::vector<PlacementRule> r = makeRules();
  return r;
}

std::vector<PlacementRule> rulesFor(const std::string& style, const std::string& room_type) {
  std::vector<PlacementRule> out;
  for (const auto& r : placementRules())
    if (r.room_type == room_type && (r.style.empty() || r.style == style)) out.push_back(r);
  return out;
}

const char* placementName(Placement p) {
  switch (p) {
    case P::Wall: return "wall";
    case P::Corner: return "corner";
    case P::Center: return "center";
    case P::Free: return "free";
    case P::OnTop: return "on top";
    case P::Around: return "around";
    case P::Front: return "front";
    case P::Mounted: return "mounted";
  }
  return "?";
}

std::string objectTableMarkdown() {
  std::ostringstream s;
  s << std::fixed;
  s << "| category | size w x d x h (m) | placement | room types: probability, count |\n";
  s << "|---|---|---|---|\n";
  for (const auto& c : objectCategories()) {
    s << "| " << c.name << " | " << std::setprecision(2) << c.size.x() << " x " << c.size.y() << " x "
      << c.size.z() << " | " << placementName(c.placement);
    for (size_t i = 0; i < c.parents.size(); ++i) s << (i ? ", " : " (") << c.parents[i];
    if (!c.parents.empty()) s << ")";
    if (c.placement == P::Mounted) s << ", bottom at " << c.mount_z << " m";
    s << " | ";
    bool first = true;
    for (const auto& r : placementRules()) {
      if (r.category != c.name) continue;
      s << (first ? "" : "; ") << r.room_type;
      first = false;
      if (!r.style.empty()) s << " (" << r.style << ")";
      s << " " << std::setprecision(2) << r.probability << ", " << r.min_count;
      if (r.max_count != r.min_count) s << "-" << r.max_count;
      if (r.m2_per_extra > 0) s << " (max grows to area / " << std::setprecision(0) << r.m2_per_extra << " m^2)";
      if (r.per_parent) s << " per parent";
    }
    s << " |\n";
  }
  return s.str();
}

}  // namespace ussnav
