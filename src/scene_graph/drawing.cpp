#include "ussnav/scene_graph/drawing.hpp"

#include <algorithm>

#include "ussnav/skeleton/graph_drawing.hpp"

namespace ussnav {
namespace {

Rgb edgeColor(const std::string& type) {
  for (int t = 0; t < kEdgeTypeCount; ++t)
    if (type == edgeTypeName(EdgeType(t))) return edgeTypeColor(EdgeType(t));
  return {90, 90, 90};
}

}  // namespace

void drawRegions(Image& img, const TopDownView& view, const SceneGraph& g, double alpha) {
  for (const SgRegion& r : g.regions) {
    const Rgb c = paletteColor(r.id);
    std::vector<Vec2> pts;
    for (int id : r.nodes) {
      const int i = g.nodeIndex(id);
      if (i >= 0) pts.push_back(view.toPx(g.nodes[size_t(i)].centroid));
    }
    const std::vector<Vec2> hull = convexOutline2d(pts);
    if (hull.size() >= 3) {
      img.fillPolygon(hull, c, alpha);
      img.polygonOutline(hull, c, 1);
    } else {
      for (const Vec2& p : pts) img.fillCircle(p.x(), p.y(), 6, c);
    }
    const Vec2 p = view.toPx(r.centroid);
    std::string text = "R";
    text += std::to_string(r.id);
    if (!r.label.empty()) text.append(" ").append(r.label);
    img.text(int(p.x()) - Image::textWidth(text) / 2, int(p.y()) - 4, text,
             {uint8_t(c[0] / 2), uint8_t(c[1] / 2), uint8_t(c[2] / 2)});
  }
}

void drawSceneGraph(Image& img, const TopDownView& view, const SceneGraph& g, const SceneDrawOptions& opt) {
  if (opt.coverage && g.coverage.cell_size > 0)
    for (const Vec3i& cell : g.coverage.visited) {
      const double s = g.coverage.cell_size;
      const Vec2 a = view.toPx(Vec2(cell.x() * s, cell.y() * s)), b = view.toPx(Vec2((cell.x() + 1) * s, (cell.y() + 1) * s));
      img.fillRect(int(std::min(a.x(), b.x())), int(std::min(a.y(), b.y())), int(std::max(a.x(), b.x())),
                   int(std::max(a.y(), b.y())), {200, 200, 200}, 0.5);
    }
  if (opt.regions) drawRegions(img, view, g, opt.region_alpha);
  if (opt.edges)
    for (const SgEdge& e : g.edges) {
      const int ia = g.nodeIndex(e.a), ib = g.nodeIndex(e.b);
      if (ia < 0 || ib < 0) continue;
      const Vec2 p = view.toPx(g.nodes[size_t(ia)].centroid), q = view.toPx(g.nodes[size_t(ib)].centroid);
      img.line(p.x(), p.y(), q.x(), q.y(), edgeColor(e.type), 1);
    }
  if (opt.nodes)
    for (const SgNode& n : g.nodes) {
      const Vec2 p = view.toPx(n.centroid);
      img.fillCircle(p.x(), p.y(), 2.5, {40, 40, 40});
    }
  if (opt.objects)
    for (const SgObject& o : g.objects) {
      const Vec2 p = view.toPx(o.centroid);
      img.fillCircle(p.x(), p.y(), 3, {150, 40, 160});
      img.text(int(p.x()) + 4, int(p.y()) - 3, o.label, {110, 20, 120});
    }
}

Aabb sceneBounds(const SceneGraph& g) {
  Aabb b;
  for (const SgNode& n : g.nodes) {
    b.extend(n.centroid);
    for (const Vec3& p : n.hull) b.extend(p);
  }
  for (const SgObject& o : g.objects) {
    b.extend(o.bbox_min);
    b.extend(o.bbox_max);
  }
  const double s = g.coverage.cell_size;
  for (const Vec3i& c : g.coverage.visited) {
    b.extend(Vec3(c.x() * s, c.y() * s, 0));
    b.extend(Vec3((c.x() + 1) * s, (c.y() + 1) * s, 0));
  }
  if (b.empty()) b = Aabb{Vec3::Zero(), Vec3::Ones()};
  return b;
}

}  // namespace ussnav
