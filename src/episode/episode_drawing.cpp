#include "ussnav/episode/episode_drawing.hpp"

#include <cstdio>

#include "ussnav/scene_graph/drawing.hpp"
#include "ussnav/sim/layout_geometry.hpp"

namespace ussnav {

Image drawEpisode(const World& world, const EpisodeRun& run, const CameraCoverage& camera,
                  const std::vector<const Object*>& goal_instances, const Pose& start) {
  const TopDownView view = TopDownView::fit(world.bounds(), 40.0);
  Image img(view.width, view.height, {215, 215, 220});
  // Camera coverage: known free cells grey-white, seen ones green.
  const double r = camera.resolution();
  const Aabb wb = world.bounds();
  for (double y = wb.min.y(); y <= wb.max.y(); y += r)
    for (double x = wb.min.x(); x <= wb.max.x(); x += r) {
      const Vec2i c = camera.cellOf(Vec2(x + 0.5 * r, y + 0.5 * r));
      if (!camera.isKnown(c)) continue;
      const Vec2 a = view.toPx(Vec2(c.x() * r, (c.y() + 1) * r)), b = view.toPx(Vec2((c.x() + 1) * r, c.y() * r));
      img.fillRect(int(a.x()), int(a.y()), int(b.x()), int(b.y()),
                   camera.isSeen(c) ? Rgb{205, 235, 200} : Rgb{250, 250, 250});
    }
  for (const auto& wall : world.walls) {
    const Vec2 a = view.toPx(wall.a), b = view.toPx(wall.b);
    img.line(a.x(), a.y(), b.x(), b.y(), {120, 120, 130}, 2);
  }
  SceneDrawOptions so;
  drawSceneGraph(img, view, run.graph, so);
  for (const Object* o : goal_instances) {
    const Aabb b = o->box.bounds();
    const Vec2 p0 = view.toPx(Vec2(b.min.x(), b.max.y())), p1 = view.toPx(Vec2(b.max.x(), b.min.y()));
    img.polygonOutline({p0, Vec2(p1.x(), p0.y()), p1, Vec2(p0.x(), p1.y())}, {240, 140, 0}, 3);
  }
  for (size_t i = 1; i < run.trajectory.size(); ++i) {
    const Vec2 p = view.toPx(run.trajectory[i - 1].pose.position), q = view.toPx(run.trajectory[i].pose.position);
    img.line(p.x(), p.y(), q.x(), q.y(), {225, 40, 40}, 2);
  }
  const Vec2 s = view.toPx(start.position);
  img.fillCircle(s.x(), s.y(), 6, {0, 150, 0});
  if (run.result.found_object) {
    const Vec2 f = view.toPx(run.result.found_object->position);
    img.fillCircle(f.x(), f.y(), 8, {30, 90, 230});
    img.fillCircle(f.x(), f.y(), 4, {255, 255, 255});
  }
  char title[256];
  const EpisodeResult& R = run.result;
  std::snprintf(title, sizeof title, "%s  goal: %s  planner: %s  %s  SPL %.2f  %.0f m  %.0f s", R.world.c_str(),
                R.goal.c_str(), R.planner.c_str(), R.success ? "FOUND" : R.end_reason.c_str(), R.spl, R.path_length_m,
                R.time_s);
  img.text(8, 8, title, {0, 0, 0}, 2);
  return img;
}

ViewerOverlay worldOverlay(const World& world, const std::vector<const Object*>& goal_instances) {
  ViewerOverlay ov;
  for (const Room& r : world.rooms) ov.rooms.push_back({r.id, r.type, r.polygon});
  for (const Wall& w : world.walls) {
    const double len = (w.b - w.a).norm();
    for (const auto& [s0, s1] : solidRuns(w, doorOpening))
      ov.walls.push_back({w.a + (w.b - w.a) * (s0 / len), w.a + (w.b - w.a) * (s1 / len)});
  }
  for (const Object* o : goal_instances) {
    const auto c = footprintCorners(o->box);
    ov.goals.push_back({o->id, o->category, std::vector<Vec2>(c.begin(), c.end())});
  }
  return ov;
}

}  // namespace ussnav
