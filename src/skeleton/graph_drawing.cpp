#include "ussnav/skeleton/graph_drawing.hpp"

#include <algorithm>

namespace ussnav {

Rgb edgeTypeColor(EdgeType t) {
  switch (t) {
    case EdgeType::Kinematic: return {40, 90, 220};
    case EdgeType::Overlap: return {30, 160, 60};
    case EdgeType::Visible: return {240, 150, 20};
    case EdgeType::Loop: return {200, 40, 200};
  }
  return {0, 0, 0};
}

std::vector<Vec2> convexOutline2d(std::vector<Vec2> pts) {
  std::sort(pts.begin(), pts.end(), [](const Vec2& a, const Vec2& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 3) return pts;
  auto cross = [](const Vec2& o, const Vec2& a, const Vec2& b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
  };
  std::vector<Vec2> hull(2 * pts.size());
  size_t k = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  for (size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  hull.resize(k - 1);
  return hull;
}

void drawConnectivityGraph(Image& img, const TopDownView& view, const ConnectivityGraph& g,
                           const GraphDrawOptions& opt) {
  auto shown = [&](int id) {
    const double z = g.node(id).center.z();
    return z >= opt.z_min && z <= opt.z_max;
  };
  if (opt.polyhedra)
    for (const ScgNode& n : g.nodes()) {
      if (!shown(n.id)) continue;
      std::vector<Vec2> px;
      for (int v : n.polyhedron.hullVertices()) px.push_back(view.toPx(n.polyhedron.points[size_t(v)]));
      const std::vector<Vec2> outline = convexOutline2d(std::move(px));
      if (outline.size() < 3) continue;
      const Rgb c = paletteColor(n.id);
      if (opt.fill_alpha > 0) img.fillPolygon(outline, c, opt.fill_alpha);
      img.polygonOutline(outline, n.satellite ? Rgb{205, 205, 205} : Rgb{160, 160, 160});
    }
  if (opt.edges)
    for (size_t e = 0; e < g.edges().size(); ++e) {
      const ScgEdge& ed = g.edges()[e];
      if (!shown(ed.a) || !shown(ed.b)) continue;
      // Edges of satellites: thin and grey, so the core graph stays readable.
      const bool faint = g.node(ed.a).satellite || g.node(ed.b).satellite;
      const std::vector<Vec3> pts = g.edgePolyline(int(e));
      for (size_t i = 1; i < pts.size(); ++i) {
        const Vec2 a = view.toPx(pts[i - 1]), b = view.toPx(pts[i]);
        img.line(a.x(), a.y(), b.x(), b.y(), faint ? Rgb{175, 175, 175} : edgeTypeColor(ed.type),
                 faint ? 1 : opt.edge_thickness);
      }
    }
  if (opt.centers)
    for (const ScgNode& n : g.nodes()) {
      if (!shown(n.id)) continue;
      const Vec2 p = view.toPx(n.center);
      if (n.satellite)
        img.fillCircle(p.x(), p.y(), 0.6 * opt.node_radius_px, {120, 120, 120});
      else
        img.fillCircle(p.x(), p.y(), opt.node_radius_px, {20, 20, 20});
    }
}

}  // namespace ussnav
