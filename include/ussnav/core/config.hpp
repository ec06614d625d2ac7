#pragma once
// Typed configuration of the whole system, one struct per stage, defaults from the paper
// (DESIGN.md table) or chosen by measurement (documented in configs/default.yaml).
// loadConfig() reads YAML over the defaults: an unknown key, a wrong type or an out-of-range
// value throws InputError naming the file and the dotted key. Overrides "a.b.c=value" apply
// after the file (the CLI's --set).

#include <filesystem>
#include <string>
#include <vector>

#include "ussnav/core/config_visitor.hpp"

namespace ussnav {

struct CameraConfig {
  int width = 160;
  int height = 120;
  double hfov_deg = 87.0;
  double vfov_deg = 58.0;
  double min_range = 0.2;
  double max_range = 5.0;
  double noise_std = 0.0;     // metres, Gaussian on depth
  double dropout = 0.0;       // probability a pixel returns no depth
  double pitch_deg = 0.0;     // camera tilt, positive looks down
  template <class V> void visit(V& v) {
    v.field("width", width, 8, 4096, "pixels");
    v.field("height", height, 8, 4096, "pixels");
    v.field("hfov_deg", hfov_deg, 10.0, 170.0, "degrees");
    v.field("vfov_deg", vfov_deg, 10.0, 170.0, "degrees");
    v.field("min_range", min_range, 0.0, 10.0, "m");
    v.field("max_range", max_range, 0.5, 100.0, "m");
    v.field("noise_std", noise_std, 0.0, 1.0, "m");
    v.field("dropout", dropout, 0.0, 1.0, "probability");
    v.field("pitch_deg", pitch_deg, -90.0, 90.0, "degrees, positive looks down");
  }
};

struct LidarConfig {
  int points_per_scan = 20000;
  double vmin_deg = -7.0;
  double vmax_deg = 52.0;
  double min_range = 0.1;
  double max_range = 40.0;
  double noise_std = 0.0;
  template <class V> void visit(V& v) {
    v.field("points_per_scan", points_per_scan, 100, 1000000, "points");
    v.field("vmin_deg", vmin_deg, -90.0, 90.0, "degrees");
    v.field("vmax_deg", vmax_deg, -90.0, 90.0, "degrees");
    v.field("min_range", min_range, 0.0, 10.0, "m");
    v.field("max_range", max_range, 1.0, 200.0, "m");
    v.field("noise_std", noise_std, 0.0, 1.0, "m");
  }
};

struct UavConfig {
  double max_speed = 1.0;          // m/s
  double max_accel = 1.0;          // m/s^2
  double max_yaw_rate_deg = 90.0;  // deg/s
  double radius = 0.25;            // collision radius, m
  double flight_height = 1.2;      // m above the floor
  template <class V> void visit(V& v) {
    v.field("max_speed", max_speed, 0.05, 20.0, "m/s");
    v.field("max_accel", max_accel, 0.05, 50.0, "m/s^2");
    v.field("max_yaw_rate_deg", max_yaw_rate_deg, 1.0, 720.0, "deg/s");
    v.field("radius", radius, 0.01, 2.0, "m");
    v.field("flight_height", flight_height, 0.2, 10.0, "m");
  }
};

struct SimConfig {
  double gt_resolution = 0.05;   // ground-truth voxel size, m
  double frame_rate_hz = 10.0;   // simulated sensor rate
  std::string map_sensor = "lidar";  // lidar | camera: what feeds the occupancy grid
  CameraConfig camera;
  LidarConfig lidar;
  UavConfig uav;
  template <class V> void visit(V& v) {
    v.field("gt_resolution", gt_resolution, 0.01, 0.2, "m");
    v.field("frame_rate_hz", frame_rate_hz, 0.5, 100.0, "Hz");
    v.choice("map_sensor", map_sensor, {"lidar", "camera"});
    v.section("camera", camera);
    v.section("lidar", lidar);
    v.section("uav", uav);
  }
};

struct GridConfig {
  double size_x = 8.0, size_y = 8.0, size_z = 4.0;  // window, m (paper: 8 x 8 x 4)
  double resolution = 0.1;                           // m (paper: 0.1)
  double log_odds_hit = 0.85;
  double log_odds_miss = -0.4;
  double log_odds_min = -2.0;
  double log_odds_max = 3.5;
  double occupied_threshold = 0.0;  // log-odds above which a cell is occupied
  template <class V> void visit(V& v) {
    v.field("size_x", size_x, 0.5, 100.0, "m");
    v.field("size_y", size_y, 0.5, 100.0, "m");
    v.field("size_z", size_z, 0.5, 50.0, "m");
    v.field("resolution", resolution, 0.02, 1.0, "m");
    v.field("log_odds_hit", log_odds_hit, 0.01, 5.0, "");
    v.field("log_odds_miss", log_odds_miss, -5.0, -0.01, "");
    v.field("log_odds_min", log_odds_min, -20.0, -0.01, "");
    v.field("log_odds_max", log_odds_max, 0.01, 20.0, "");
    v.field("occupied_threshold", occupied_threshold, -5.0, 5.0, "");
  }
};

struct CoverageConfig {
  double cell_size = 1.0;            // m, square cells in x-y
  double cell_height = 4.0;          // m, vertical extent of one cell (window height)
  double visited_unknown_fraction = 0.5;  // visited when unknown voxels < this fraction
  double min_window_fraction = 0.5;  // judge a cell only when this much of it is in the window
  template <class V> void visit(V& v) {
    v.field("cell_size", cell_size, 0.2, 10.0, "m");
    v.field("cell_height", cell_height, 0.2, 50.0, "m");
    v.field("visited_unknown_fraction", visited_unknown_fraction, 0.0, 1.0, "fraction");
    v.field("min_window_fraction", min_window_fraction, 0.01, 1.0, "fraction");
  }
};

struct MappingConfig {
  GridConfig grid;
  CoverageConfig coverage;
  template <class V> void visit(V& v) {
    v.section("grid", grid);
    v.section("coverage", coverage);
  }
};

struct SkeletonConfig {
  int sphere_samples = 50;          // Fibonacci sphere vertices (paper: 50)
  double max_radius = 1.4;          // max ray length, m (paper: 1.4)
  double max_extension = 2.0;       // max seed extension, m (paper: 2.0)
  double min_center_distance = 1.0; // no new polyhedron within this of an existing centre
  double visibility_radius = 2.5;   // visible edges, m
  double loop_path_max = 3.0;       // loop-closure edges when grid path <= this, m
  double robot_radius = 0.25;       // safety margin for seeds, m
  int max_cluster_faces = 12;       // split boundary clusters above this many faces
  double max_normal_divergence_deg = 45.0;
  double forced_edge_weight = 0.01; // epsilon for forced links (paper)
  bool unknown_is_contact = true;   // rays stop at unknown space
  int max_expansions_per_frame = 200;
  int seed_retries = 4;             // fallback seeds from a surface's free vertices
  double max_unknown_gap = 0.2;     // unknown stretches up to this long are sensor holes, m
  template <class V> void visit(V& v) {
    v.field("sphere_samples", sphere_samples, 8, 2000, "points");
    v.field("max_radius", max_radius, 0.2, 10.0, "m");
    v.field("max_extension", max_extension, 0.1, 10.0, "m");
    v.field("min_center_distance", min_center_distance, 0.05, 10.0, "m");
    v.field("visibility_radius", visibility_radius, 0.0, 20.0, "m");
    v.field("loop_path_max", loop_path_max, 0.0, 50.0, "m");
    v.field("robot_radius", robot_radius, 0.0, 2.0, "m");
    v.field("max_cluster_faces", max_cluster_faces, 1, 1000, "faces");
    v.field("max_normal_divergence_deg", max_normal_divergence_deg, 1.0, 180.0, "degrees");
    v.field("forced_edge_weight", forced_edge_weight, 0.0, 1.0, "");
    v.field("unknown_is_contact", unknown_is_contact);
    v.field("max_expansions_per_frame", max_expansions_per_frame, 1, 100000, "");
    v.field("seed_retries", seed_retries, 0, 100, "");
    v.field("max_unknown_gap", max_unknown_gap, 0.0, 2.0, "m");
  }
};

struct Config {
  SimConfig sim;
  MappingConfig mapping;
  SkeletonConfig skeleton;
  template <class V> void visit(V& v) {
    v.section("sim", sim);
    v.section("mapping", mapping);
    v.section("skeleton", skeleton);
  }
};

// Reads `path` (YAML) over the defaults, then applies `overrides` ("a.b.c=value").
Config loadConfig(const std::filesystem::path& path, const std::vector<std::string>& overrides = {});
// Defaults plus overrides, no file.
Config defaultConfig(const std::vector<std::string>& overrides = {});
// The config as YAML text, every key, in declaration order.
std::string configToYaml(const Config& cfg);
// Cross-field checks (e.g. lidar vmin < vmax); throws InputError naming `source` and the key.
void validateConfig(const Config& cfg, const std::string& source);
// The repository's configs/default.yaml if it exists, else empty.
std::filesystem::path defaultConfigPath();

}  // namespace ussnav
