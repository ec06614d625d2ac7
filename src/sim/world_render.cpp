#include "ussnav/sim/world_render.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "ussnav/sim/layout_geometry.hpp"
#include "ussnav/sim/object_table.hpp"

namespace ussnav {

namespace {

constexpr Rgb kWall{0, 0, 0}, kDoor{220, 0, 200}, kWindow{0, 150, 220}, kStart{0, 160, 60};
constexpr Rgb kText{40, 40, 40};
constexpr int kFooter = 40;

uint32_t fnv(const std::string& s) {
  uint32_t h = 2166136261u;
  for (unsigned char c : s) h = (h ^ c) * 16777619u;
  return h;
}

Rgb mix(Rgb a, Rgb b, double t) {
  return {uint8_t(std::lround(a[0] * (1 - t) + b[0] * t)), uint8_t(std::lround(a[1] * (1 - t) + b[1] * t)),
          uint8_t(std::lround(a[2] * (1 - t) + b[2] * t))};
}

Rgb categoryColor(const std::string& cat) {
  const auto& cats = objectCategories();
  for (size_t i = 0; i < cats.size(); ++i)
    if (cats[i].name == cat) return mix(paletteColor(int(i)), {0, 0, 0}, 0.35);
  return mix(paletteColor(int(fnv(cat) % 997)), {0, 0, 0}, 0.35);
}

struct LabelBoxes {
  std::vector<std::array<int, 4>> boxes;  // x0, y0, x1, y1
  bool free(int x0, int y0, int x1, int y1, int w, int h) const {
    if (x0 < 0 || y0 < 0 || x1 >= w || y1 >= h) return false;
    for (const auto& b : boxes)
      if (x0 <= b[2] && b[0] <= x1 && y0 <= b[3] && b[1] <= y1) return false;
    return true;
  }
};

// Text with a light backing so it stays readable over fills and outlines.
void label(Image& img, int x, int y, const std::string& s, int scale, Rgb c) {
  img.fillRect(x - 1, y - 1, x + Image::textWidth(s, scale) - scale, y + 7 * scale, {255, 255, 255}, 0.65);
  img.text(x, y, s, c, scale);
}

// The point of a polygon farthest from its boundary (label anchor; works for L shapes).
Vec2 deepestPoint(const std::vector<Vec2>& poly) {
  Vec2 lo = poly[0], hi = poly[0];
  for (const auto& p : poly) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double step = std::max(0.1, std::max(hi.x() - lo.x(), hi.y() - lo.y()) / 60.0);
  Vec2 best = polygonCentroid(poly);
  double bd = pointInPolygon(best, poly) ? distanceToBoundary(best, poly) : -1.0;
  for (double y = lo.y() + step / 2; y < hi.y(); y += step)
    for (double x = lo.x() + step / 2; x < hi.x(); x += step) {
      const Vec2 p(x, y);
      if (!pointInPolygon(p, poly)) continue;
      const double d = distanceToBoundary(p, poly);
      if (d > bd + 0.15) bd = d, best = p;  // prefer the centroid unless clearly shallower
    }
  return best;
}

void drawVoxels(Image& img, const TopDownView& v, const ObstacleVoxels& ob) {
  // Occupied voxels per column, darker for more: walls (full height) dark, a floor and a
  // ceiling (two voxels) pale, furniture and low clutter in between.
  std::map<std::pair<int, int>, int> count;
  int kmin = INT32_MAX, kmax = INT32_MIN;
  for (const auto& c : ob.cells) {
    ++count[std::make_pair(c.x(), c.y())];
    kmin = std::min(kmin, c.z());
    kmax = std::max(kmax, c.z());
  }
  const double span = std::max(1, kmax - kmin + 1);
  for (const auto& [ij, n] : count) {
    const Vec2 lo = v.toPx(Vec2(ob.origin.x() + ij.first * ob.resolution, ob.origin.y() + ij.second * ob.resolution));
    const Vec2 hi = v.toPx(Vec2(ob.origin.x() + (ij.first + 1) * ob.resolution,
                                ob.origin.y() + (ij.second + 1) * ob.resolution));
    const uint8_t g = uint8_t(std::lround(225 - 205 * std::min(1.0, n / span)));
    img.fillRect(int(std::floor(lo.x())), int(std::ceil(hi.y())), int(std::ceil(hi.x())) - 1,
                 int(std::floor(lo.y())), {g, g, g});
  }
}

}  // namespace

Rgb roomTypeColor(const std::string& type) {
  static const std::map<std::string, Rgb> kColors{
      {"corridor", {228, 228, 228}},     {"hallway", {226, 224, 212}},   {"office", {190, 214, 245}},
      {"meeting room", {196, 234, 196}}, {"kitchen", {255, 222, 176}},   {"bathroom", {176, 228, 234}},
      {"storage", {216, 202, 186}},      {"living room", {250, 210, 212}}, {"bedroom", {224, 208, 246}},
      {"dining room", {248, 238, 176}},  {"study", {204, 230, 214}},     {"laundry room", {200, 222, 240}},
  };
  auto it = kColors.find(type);
  if (it != kColors.end()) return it->second;
  return mix(paletteColor(int(fnv(type) % 997)), {255, 255, 255}, 0.5);
}

Image renderWorld(const World& w, const RenderOptions& opt) {
  Aabb b = w.bounds();
  if (b.empty()) b.extend(Vec3::Zero()), b.extend(Vec3(1, 1, 1));
  const TopDownView v = TopDownView::fit(b, opt.px_per_m, 30, opt.max_px);
  const double ppm = v.px_per_m;
  Image img(std::max(v.width, 360), v.height + kFooter);
  LabelBoxes labels;

  if (!w.obstacles.cells.empty()) drawVoxels(img, v, w.obstacles);

  auto px = [&](const std::vector<Vec2>& poly) {
    std::vector<Vec2> out;
    for (const auto& p : poly) out.push_back(v.toPx(p));
    return out;
  };
  for (const auto& r : w.rooms) img.fillPolygon(px(r.polygon), roomTypeColor(r.type), w.obstacles.cells.empty() ? 1.0 : 0.5);

  for (const auto& o : w.objects) {
    const auto c = footprintCorners(o.box);
    const std::vector<Vec2> poly(c.begin(), c.end());
    const Rgb col = categoryColor(o.category);
    img.fillPolygon(px(poly), col, 0.25);
    img.polygonOutline(px(poly), col, ppm >= 25 ? 2 : 1);
  }

  // Walls as filled strips, their openings left out; doors magenta across the gap.
  for (const auto& wl : w.walls) {
    const double len = (wl.b - wl.a).norm();
    if (len < 1e-9) continue;
    const Vec2 d = (wl.b - wl.a) / len, n(-d.y(), d.x());
    const Vec2 h = n * (0.5 * wl.thickness);
    for (const auto& [s0, s1] : solidRuns(wl, anyOpening)) {
      const Vec2 p0 = wl.a + d * s0, p1 = wl.a + d * s1;
      img.fillPolygon(px({p0 - h, p1 - h, p1 + h, p0 + h}), kWall);
      // Thin walls would vanish below a pixel; keep at least a 2-px line.
      if (wl.thickness * ppm < 2.0) {
        const Vec2 q0 = v.toPx(p0), q1 = v.toPx(p1);
        img.line(q0.x(), q0.y(), q1.x(), q1.y(), kWall, 2);
      }
    }
    for (const auto& op : wl.openings) {
      const Vec2 q0 = v.toPx(Vec2(wl.a + d * op.start)), q1 = v.toPx(Vec2(wl.a + d * op.end));
      const bool window = op.bottom > 0.3;
      img.line(q0.x(), q0.y(), q1.x(), q1.y(), window ? kWindow : kDoor, window ? 1 : 3);
    }
  }
  // Doors that name a centre but whose wall has no opening still get a mark.
  for (const auto& d : w.doors) {
    const Vec2 c = v.toPx(d.center);
    img.fillCircle(c.x(), c.y(), std::max(2.0, 0.06 * ppm), kDoor);
  }

  // Start pose: a disc of the UAV's size with a heading tick.
  {
    const Vec2 c = v.toPx(Vec2(w.start.position.x(), w.start.position.y()));
    const Vec2 t = v.toPx(Vec2(w.start.position.x() + 0.6 * std::cos(w.start.yaw),
                               w.start.position.y() + 0.6 * std::sin(w.start.yaw)));
    img.fillCircle(c.x(), c.y(), std::max(3.0, 0.25 * ppm), kStart);
    img.line(c.x(), c.y(), t.x(), t.y(), kStart, 3);
    labels.boxes.push_back({int(c.x() - 0.3 * ppm), int(c.y() - 0.3 * ppm), int(c.x() + 0.3 * ppm), int(c.y() + 0.3 * ppm)});
  }

  // Room labels first (they matter most), then object labels where they still fit.
  for (const auto& r : w.rooms) {
    const Vec2 c = v.toPx(deepestPoint(r.polygon));
    Vec2 lo = r.polygon[0], hi = lo;
    for (const auto& p : r.polygon) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    const double room_px = (hi.x() - lo.x()) * ppm;
    const int scale = Image::textWidth(r.type, 2) <= room_px - 8 ? 2 : 1;
    const int tw = Image::textWidth(r.type, scale), th = 7 * scale;
    int x = int(c.x()) - tw / 2, y = int(c.y()) - th / 2;
    // Slide up or down off objects' labels is not needed: room labels go first.
    label(img, x, y, r.type, scale, kText);
    labels.boxes.push_back({x - 1, y - 1, x + tw, y + th});
  }
  if (opt.object_labels) {
    for (const auto& o : w.objects) {
      const Aabb ob = o.box.bounds();
      const Vec2 c = v.toPx(Vec2(o.box.center.x(), o.box.center.y()));
      const Vec2 top = v.toPx(Vec2(o.box.center.x(), ob.max.y()));
      const Vec2 bottom = v.toPx(Vec2(o.box.center.x(), ob.min.y()));
      const int tw = Image::textWidth(o.category), th = 7;
      const Rgb col = categoryColor(o.category);
      const std::array<Vec2, 3> tries{Vec2(c.x(), c.y() - th / 2.0), Vec2(c.x(), top.y() - th - 3),
                                      Vec2(c.x(), bottom.y() + 3)};
      for (const auto& t : tries) {
        const int x = int(t.x()) - tw / 2, y = int(t.y());
        if (!labels.free(x - 1, y - 1, x + tw, y + th, img.width(), v.height)) continue;
        label(img, x, y, o.category, 1, col);
        labels.boxes.push_back({x - 1, y - 1, x + tw, y + th});
        break;
      }
    }
  }

  // Footer: scale bar and a one-line caption.
  const int y0 = v.height + 8;
  double bar_m = 1;
  for (double m : {1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0})
    if (m * ppm <= 220) bar_m = m;
  const int bar_px = int(std::lround(bar_m * ppm));
  img.fillRect(0, v.height, img.width() - 1, img.height() - 1, {255, 255, 255});
  const int x0 = 20;
  img.fillRect(x0, y0 + 8, x0 + bar_px, y0 + 12, {0, 0, 0});
  for (int m = 0; m <= int(bar_m); m += std::max(1, int(bar_m) / 5)) {
    const int x = x0 + int(std::lround(m * ppm));
    img.fillRect(x - 1, y0 + 3, x, y0 + 12, {0, 0, 0});
  }
  img.text(x0, y0 + 17, "0", kText);
  const std::string unit = (bar_m == std::floor(bar_m) ? std::to_string(int(bar_m)) : std::to_string(bar_m)) + " m";
  img.text(x0 + bar_px - Image::textWidth(unit) / 2, y0 + 17, unit, kText);
  std::string caption = w.name.empty() ? "world" : w.name;
  caption += "  " + std::to_string(w.rooms.size()) + " rooms  " + std::to_string(w.doors.size()) + " doors  " +
             std::to_string(w.objects.size()) + " objects";
  if (!w.obstacles.cells.empty()) caption += "  " + std::to_string(w.obstacles.cells.size()) + " voxels";
  img.text(x0 + bar_px + 40, y0 + 6, caption, kText);
  return img;
}

}  // namespace ussnav
