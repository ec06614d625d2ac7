// The two building styles as rectangle plans (decimetres). Both are banded: rows of rooms
// along one or two circulation strips (corridors; a flat's hallway), widths drawn per room
// type and stretched until the floor reaches the requested area.

#include <algorithm>
#include <cmath>

#include "floorplan_internal.hpp"

namespace ussnav::floorplan {

namespace {

struct Slot {
  std::string type;
  int width = 0;        // dm along the row
  double weight = 1.0;  // share of the row's slack this slot takes
  int room = -1;        // plan room index it belongs to (-1: a new room)
};

struct TypeSpec {
  const char* type;
  int min_dm, max_dm;
  double weight;
};

// Widths along the row (dm) and how eagerly each type absorbs spare length.
constexpr TypeSpec kWidths[] = {
    {"office", 30, 45, 1.0},      {"meeting room", 45, 70, 1.0}, {"kitchen", 35, 50, 0.6},
    {"bathroom", 22, 30, 0.25},   {"storage", 18, 26, 0.2},     {"bedroom", 32, 45, 1.0},
    {"dining room", 32, 42, 0.7}, {"study", 26, 34, 0.5},       {"laundry room", 18, 24, 0.2},
    {"living room", 30, 45, 0.8},
};

Slot makeSlot(const std::string& type, Rng& rng) {
  for (const auto& s : kWidths)
    if (type == s.type) return {type, rng.uniformInt(s.min_dm, s.max_dm), s.weight, -1};
  return {type, 30, 1.0, -1};
}

void shuffle(std::vector<Slot>& v, Rng& rng) {
  for (int i = int(v.size()) - 1; i > 0; --i) std::swap(v[i], v[rng.uniformInt(0, i)]);
}

int rowSum(const std::vector<Slot>& row) {
  int s = 0;
  for (const auto& x : row) s += x.width;
  return s;
}

// Stretches a row to `length` dm, handing the slack out by weight (remainder to the first).
void stretch(std::vector<Slot>& row, int length) {
  int slack = length - rowSum(row);
  double wsum = 0;
  for (const auto& s : row) wsum += s.weight;
  if (slack <= 0 || row.empty()) return;
  if (wsum <= 0) {
    row.front().width += slack;
    return;
  }
  int given = 0;
  for (auto& s : row) {
    const int add = int(std::floor(slack * s.weight / wsum));
    s.width += add;
    given += add;
  }
  for (size_t i = 0; given < slack; i = (i + 1) % row.size())
    if (row[i].weight > 0) ++row[i].width, ++given;
}

// Lays `row` out from x0 in direction dir (+1 / -1) over y0..y1, adding rooms to the plan.
void placeRow(const std::vector<Slot>& row, int x0, int dir, int y0, int y1, int group, Plan& plan) {
  int x = x0;
  for (const auto& s : row) {
    const int xa = dir > 0 ? x : x - s.width, xb = dir > 0 ? x + s.width : x;
    const RectDm r{xa, y0, xb, y1};
    if (s.room >= 0) {
      plan.rooms[s.room].rects.push_back(r);
    } else {
      plan.rooms.push_back({s.type, {r}, group});
    }
    x += dir * s.width;
  }
}

int ceilDiv(double a, int b) { return int(std::ceil(a / b - 1e-9)); }

}  // namespace

Plan planOffice(int rooms, double min_area_m2, Rng& rng) {
  Plan plan;
  plan.doors.circulation = {"corridor"};
  plan.doors.extra = {{"corridor", "corridor", 1.0, false},
                      {"office", "office", 0.12, false},
                      {"meeting room", "office", 0.08, false}};
  plan.doors.two_door_types = {"meeting room"};
  plan.start_type = "corridor";

  const bool two = rooms <= 12 ? false : rooms >= 20 ? true : rng.bernoulli(0.5);
  const bool end_room = !two && rooms >= 8 && rng.bernoulli(0.5);
  const std::string end_type = end_room ? (rng.bernoulli(0.5) ? "meeting room" : "office") : "";
  const int n = rooms - (two ? 2 : 1) - (end_room ? 1 : 0);
  int nb = n >= 10 ? 2 : 1, ns = n >= 14 ? 2 : 1, nm = std::max(1, n / 7);
  if (end_type == "meeting room") nm -= 1;
  int no = n - 1 - nb - ns - nm;
  if (no < 0) ns += no, no = 0;  // only for the smallest floors
  std::vector<Slot> slots{makeSlot("kitchen", rng)};
  for (int i = 0; i < nb; ++i) slots.push_back(makeSlot("bathroom", rng));
  for (int i = 0; i < ns; ++i) slots.push_back(makeSlot("storage", rng));
  for (int i = 0; i < nm; ++i) slots.push_back(makeSlot("meeting room", rng));
  for (int i = 0; i < no; ++i) slots.push_back(makeSlot("office", rng));
  shuffle(slots, rng);

  const int cw = rng.uniformInt(18, 24);
  const int d_low = rng.uniformInt(45, 60), d_high = rng.uniformInt(45, 60), d_mid = rng.uniformInt(50, 70);
  // Rows bottom to top: low [corridor 2, mid] corridor 1, high.
  std::vector<std::vector<Slot>> rows(two ? 3 : 2);
  const int mid = two ? 1 : -1;
  std::vector<int> sums(rows.size(), 0);
  if (two) sums[mid] = cw;  // the connector between the corridors crosses the middle row
  for (auto& s : slots) {
    const size_t r = size_t(std::min_element(sums.begin(), sums.end()) - sums.begin());
    sums[r] += s.width;
    rows[r].push_back(s);
  }
  const int depth = two ? d_low + cw + d_mid + cw + d_high : d_low + cw + d_high;
  const int end_w = end_room ? rng.uniformInt(50, 80) : 0;
  int length = *std::max_element(sums.begin(), sums.end());
  length = std::max(length, ceilDiv(min_area_m2 * 100.0, depth) - end_w);

  // Corridors first: room 1 is the main corridor (and holds the connector when there are two).
  if (two) {
    const int y_c2 = d_low, y_mid = d_low + cw, y_c1 = y_mid + d_mid;
    plan.rooms.push_back({"corridor", {{0, y_c1, length, y_c1 + cw}}, 0});
    plan.rooms.push_back({"corridor", {{0, y_c2, length, y_c2 + cw}}, 0});
    Slot conn{"corridor", cw, 0.0, 0};
    auto& mrow = rows[mid];
    const int at = mrow.size() >= 2 ? rng.uniformInt(1, int(mrow.size()) - 1) : int(mrow.size());
    mrow.insert(mrow.begin() + at, conn);
    for (auto& row : rows) stretch(row, length);
    placeRow(rows[0], 0, +1, 0, d_low, 0, plan);
    placeRow(rows[1], 0, +1, y_mid, y_c1, 0, plan);
    placeRow(rows[2], 0, +1, y_c1 + cw, depth, 0, plan);
  } else {
    plan.rooms.push_back({"corridor", {{0, d_low, length, d_low + cw}}, 0});
    for (auto& row : rows) stretch(row, length);
    placeRow(rows[0], 0, +1, 0, d_low, 0, plan);
    placeRow(rows[1], 0, +1, d_low + cw, depth, 0, plan);
  }
  if (end_room) plan.rooms.push_back({end_type, {{length, 0, length + end_w, depth}}, 0});
  return plan;
}

Plan planApartment(int rooms, double min_area_m2, Rng& rng) {
  Plan plan;
  plan.doors.circulation = {"hallway", "living room"};
  plan.doors.extra = {{"hallway", "hallway", 1.0, true},
                      {"kitchen", "living room", 0.7, false},
                      {"dining room", "living room", 0.8, false},
                      {"kitchen", "dining room", 0.8, false},
                      {"bedroom", "bathroom", 0.15, false}};
  plan.start_type = "hallway";

  const bool two = rooms >= 12 && (rooms >= 16 || rng.bernoulli(0.6));
  const int flats = two ? 2 : 1;
  const int per[2] = {two ? rooms / 2 : rooms, rooms - rooms / 2};
  const int d_bot = rng.uniformInt(42, 55), hw = rng.uniformInt(16, 20), d_top = rng.uniformInt(50, 65);
  const int depth = d_bot + hw + d_top;
  static const char* kExtras[] = {"bedroom", "dining room", "bedroom", "study", "bathroom", "storage",
                                  "bedroom", "laundry room", "study", "bathroom", "bedroom", "storage"};

  struct Flat {
    int living_w = 0;
    bool l_shape = false;
    std::vector<Slot> top, bottom;
    int length = 0;  // of the hallway and the top row, dm
  };
  std::vector<Flat> fl(flats);
  int total = 0;
  for (int f = 0; f < flats; ++f) {
    Flat& F = fl[f];
    F.living_w = rng.uniformInt(44, 60);
    F.l_shape = rng.bernoulli(0.4);
    std::vector<Slot> front, others;  // front: kitchen side, next to the living room
    front.push_back(makeSlot("kitchen", rng));
    others.push_back(makeSlot("bathroom", rng));
    others.push_back(makeSlot("bedroom", rng));
    for (int e = 0; e < per[f] - 5; ++e) {
      const std::string t = kExtras[e % std::size(kExtras)];
      (t == "dining room" ? front : others).push_back(makeSlot(t, rng));
    }
    shuffle(front, rng);
    shuffle(others, rng);
    if (F.l_shape) {
      Slot ext = makeSlot("living room", rng);
      ext.room = -2;  // resolved to the flat's living room when placed
      F.top.push_back(ext);
    }
    for (auto& s : front) F.top.push_back(s);
    // The bottom row also runs under the living room, so it starts living_w ahead.
    int top = rowSum(F.top), bottom = -F.living_w;
    for (auto& s : others) {
      if (top < bottom) F.top.push_back(s), top += s.width;
      else F.bottom.push_back(s), bottom += s.width;
    }
    F.length = std::max({top, bottom, 20});
    total += F.living_w + F.length;
  }
  // Too small a floor: widen the living rooms a little (up to 9 m), then lengthen the flats.
  const int need = ceilDiv(min_area_m2 * 100.0, depth);
  for (int f = 0; need > total && f < flats; ++f) {
    const int add = std::min((need - total) / (3 * (flats - f)), 90 - fl[f].living_w);
    if (add > 0) fl[f].living_w += add, total += add;
  }
  for (int f = 0; need > total && f < flats; ++f) {
    const int add = (need - total + (flats - f) - 1) / (flats - f);
    fl[f].length += add;
    total += add;
  }

  // Flat 0 grows right from x = 0 with its living room on the left; flat 1 is its mirror
  // image on the right, so the two hallways meet in the middle.
  const int width_all = total;
  for (int f = 0; f < flats; ++f) {
    Flat& F = fl[f];
    const int dir = f == 0 ? +1 : -1;
    const int outer = f == 0 ? 0 : width_all;
    const int inner = outer + dir * F.living_w;  // where the hallway starts
    const int hall_end = inner + dir * F.length;
    const int living = int(plan.rooms.size());
    plan.rooms.push_back({"living room", {{std::min(outer, inner), d_bot, std::max(outer, inner), depth}}, f});
    plan.rooms.push_back({"hallway", {{std::min(inner, hall_end), d_bot, std::max(inner, hall_end), d_bot + hw}}, f});
    for (auto& s : F.top)
      if (s.room == -2) s.room = living;
    stretch(F.top, F.length);
    stretch(F.bottom, F.living_w + F.length);
    placeRow(F.top, inner, dir, d_bot + hw, depth, f, plan);
    placeRow(F.bottom, outer, dir, 0, d_bot, f, plan);
  }
  return plan;
}

}  // namespace ussnav::floorplan
