#include "ussnav/sim/simulator.hpp"

#include "ussnav/core/error.hpp"

namespace ussnav {

Simulator::Simulator(World world, const Config& cfg, uint64_t seed)
    : world_(std::move(world)),
      cfg_(cfg),
      gt_(world_, cfg.sim.gt_resolution),
      planner_(gt_, world_, cfg.sim.uav.flight_height, cfg.sim.uav.radius),
      camera_(cfg.sim.camera, seed * 2 + 1),
      lidar_(cfg.sim.lidar, seed * 2 + 2) {}

SensedFrame Simulator::sense(const Pose& pose, double time) {
  SensedFrame f;
  f.pose = pose;
  f.time = time;
  if (cfg_.sim.map_sensor == "lidar") f.scan = lidar_.scan(gt_, pose, time);
  f.depth = camera_.render(gt_, pose, time);
  return f;
}

std::unordered_map<uint32_t, std::string> Simulator::instanceLabels() const {
  std::unordered_map<uint32_t, std::string> m;
  for (const auto& o : world_.objects) m[uint32_t(o.id)] = o.category;
  return m;
}

Pose Simulator::startPose() const {
  Pose p = world_.start;
  const Vec2 xy = p.position.head<2>();
  auto free = planner_.freeAt(xy) ? std::optional<Vec2>(xy) : planner_.nearestFree(xy, 3.0);
  if (!free) {
    // Fall back to any free cell (worlds whose start pose is unusable).
    const auto samples = planner_.freeSamples(10);
    if (samples.empty())
      throw InputError(world_.name, "start", "no free space at flight height for the UAV");
    free = samples[samples.size() / 2];
  }
  p.position = Vec3(free->x(), free->y(), planner_.flightZ());
  return p;
}

}  // namespace ussnav
