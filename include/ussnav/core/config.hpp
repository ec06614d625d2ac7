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
  bool carve_obstacles = false;     // cut occupied voxels out of a hull (else: record them)
  int max_carve_cuts = 24;          // at most this many cuts per polyhedron
  double edge_clearance = 0.05;     // edges and path shortcuts keep a tube this wide clear, m
  bool gap_fill = true;             // seed polyhedra in observed free space nothing covers
  double gap_spacing = 0.5;         // lattice of gap-seed candidates, m
  double gap_scan_radius = 4.0;     // candidates within this of the UAV, m
  double gap_min_center_distance = 0.6;  // gap seeds: no existing centre within this, m
  double gap_clearance = 0.5;       // gap seeds: no obstacle within this, m (>= robot_radius)
  bool satellite_fill = true;       // then fill what is left with satellite polyhedra (below)
  double satellite_spacing = 0.3;   // lattice of satellite-seed candidates, m
  double satellite_min_center_distance = 0.4;  // satellites: no existing centre within this, m
  double satellite_clearance = 0.25;  // satellites: no obstacle within this, m (>= robot_radius)
  int refine_rays = 0;              // extra rays through hull faces that miss free space
  double refine_min_gain = 0.1;     // a refinement ray counts when it reaches this past the face, m
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
    v.field("carve_obstacles", carve_obstacles);
    v.field("max_carve_cuts", max_carve_cuts, 0, 1000, "");
    v.field("edge_clearance", edge_clearance, 0.0, 1.0, "m");
    v.field("gap_fill", gap_fill);
    v.field("gap_spacing", gap_spacing, 0.1, 5.0, "m");
    v.field("gap_scan_radius", gap_scan_radius, 0.0, 50.0, "m");
    v.field("gap_min_center_distance", gap_min_center_distance, 0.0, 10.0, "m");
    v.field("gap_clearance", gap_clearance, 0.0, 5.0, "m");
    v.field("satellite_fill", satellite_fill);
    v.field("satellite_spacing", satellite_spacing, 0.1, 5.0, "m");
    v.field("satellite_min_center_distance", satellite_min_center_distance, 0.0, 10.0, "m");
    v.field("satellite_clearance", satellite_clearance, 0.0, 5.0, "m");
    v.field("refine_rays", refine_rays, 0, 2000, "rays");
    v.field("refine_min_gain", refine_min_gain, 0.0, 5.0, "m");
  }
};

struct PerceptionConfig {
  std::string detector = "oracle";      // oracle (simulator instance ids); onnx comes later
  double miss_prob = 0.1;               // oracle: chance an instance is not reported in a frame
  double confusion_prob = 0.05;         // oracle: chance its label is swapped for a similar one
  int erosion_px = 1;                   // oracle: mask erosion, pixels (detector masks are tight)
  int min_pixels = 20;                  // oracle: smaller masks are not reported
  double max_range = 4.5;               // oracle: masks whose median depth is farther are dropped, m
  double score = 0.9;                   // oracle: confidence reported with every detection
  std::string text_encoder = "wordnet"; // wordnet (built-in stand-in for Mobile-CLIP) | ngram
  int embedding_dim = 512;              // text embedding size (Mobile-CLIP: 512)
  template <class V> void visit(V& v) {
    v.choice("detector", detector, {"oracle"});
    v.field("miss_prob", miss_prob, 0.0, 1.0, "probability");
    v.field("confusion_prob", confusion_prob, 0.0, 1.0, "probability");
    v.field("erosion_px", erosion_px, 0, 50, "pixels");
    v.field("min_pixels", min_pixels, 1, 1000000, "pixels");
    v.field("max_range", max_range, 0.1, 100.0, "m");
    v.field("score", score, 0.0, 1.0, "confidence");
    v.choice("text_encoder", text_encoder, {"wordnet", "ngram"});
    v.field("embedding_dim", embedding_dim, 16, 4096, "dimensions");
  }
};

struct ObjectsConfig {
  double association_radius = 2.0;  // candidates within this of the new centroid, m (paper)
  double semantic_cos = 0.75;       // semantic match: cosine above this (paper)
  double semantic_overlap = 0.1;    // ... and overlap new->old above this (paper)
  double geometric_overlap = 0.5;   // geometric match: overlap above this both ways (paper)
  double tau = 0.1;                 // point match distance in the overlap, m (paper's tau)
  double voxel_size = 0.05;         // object clouds are voxel-downsampled to this, m
  int min_points = 10;              // observations with fewer points are rejected
  int max_points_per_object = 5000; // above this an object's cloud is coarsened (voxel x2)
  int min_observations_to_confirm = 2;  // objects seen fewer times are tentative
  // Duplicate merging: two objects whose labels agree (embedding cosine > semantic_cos) and whose
  // boxes, each grown by voxel_size, overlap by more than this fraction of the smaller box are
  // one object seen from two sides; the younger is absorbed by the older. 0 = never merge.
  double merge_box_overlap = 0.3;
  template <class V> void visit(V& v) {
    v.field("association_radius", association_radius, 0.1, 20.0, "m");
    v.field("semantic_cos", semantic_cos, -1.0, 1.0, "cosine");
    v.field("semantic_overlap", semantic_overlap, 0.0, 1.0, "fraction");
    v.field("geometric_overlap", geometric_overlap, 0.0, 1.0, "fraction");
    v.field("tau", tau, 0.005, 2.0, "m");
    v.field("voxel_size", voxel_size, 0.005, 1.0, "m");
    v.field("min_points", min_points, 1, 1000000, "points");
    v.field("max_points_per_object", max_points_per_object, 10, 10000000, "points");
    v.field("min_observations_to_confirm", min_observations_to_confirm, 1, 1000, "observations");
    v.field("merge_box_overlap", merge_box_overlap, 0.0, 1.0, "fraction of the smaller box, 0 = off");
  }
};

struct RegionsConfig {
  double resolution = 0.1;          // Leiden CPM resolution (paper: 0.02)
  double beta = 0.01;                // Leiden refinement randomness
  int iterations = -1;               // Leiden iterations; -1 = until the partition is stable
  int merge_shared_border_nodes = 12; // merge two adjacent regions sharing MORE border nodes
  double border_edge_min_weight = 0.5;  // lighter (forced) edges never make a border node
  double merge_min_opening_m = 0.0;  // and only through an opening this wide (0: any)
  int min_region_nodes = 3;          // smaller regions join their most connected neighbour
  int seed = 1;                      // igraph RNG seed, reset before every Leiden call
  bool incremental = true;           // false: Leiden on the whole graph every update
  bool warm_start = true;            // start Leiden from the previous membership
  template <class V> void visit(V& v) {
    v.field("resolution", resolution, 1e-6, 10.0, "CPM resolution");
    v.field("beta", beta, 1e-6, 10.0, "refinement randomness");
    v.field("iterations", iterations, -1, 1000, "-1 = until stable, 0 is rejected");
    v.field("merge_shared_border_nodes", merge_shared_border_nodes, 0, 100000, "nodes");
    v.field("border_edge_min_weight", border_edge_min_weight, 0.0, 1e9, "edge weight");
    v.field("merge_min_opening_m", merge_min_opening_m, 0.0, 1000.0, "m");
    v.field("min_region_nodes", min_region_nodes, 1, 100000, "nodes");
    v.field("seed", seed, 0, 2147483647, "");
    v.field("incremental", incremental);
    v.field("warm_start", warm_start);
  }
};

struct ExplorationConfig {
  double band_z_min = 0.3;          // frontier cells: voxel centre z in [band_z_min, band_z_max], m
  double band_z_max = 2.1;
  int min_cluster_cells = 20;       // smaller connected groups of frontier cells are not frontiers
  double max_cluster_extent = 2.0;  // split a cluster (PCA) while longer than this along its axis, m
  bool remember_known_band = true;  // true: free space cut off by the window's edge is a frontier
                                    // only where the voxel beyond was never known (BandMemory)
  bool open_in_visited = true;      // with remember_known_band: a visited Coverage Mask cell still
                                    // holds frontier voxels whose x-y neighbour was never known
  double open_in_visited_above = 0.25; // ... only voxels whose centre is at viewpoint_height or
                                    // at most this far above it, m: below the sensor the LiDAR
                                    // (-7 deg) leaves a never-known disc around the UAV
  double viewpoint_height = 1.2;    // viewpoints at this z (flight height), m
  double viewpoint_r_min = 1.5;     // viewpoint rings around the centroid, m (FUEL)
  double viewpoint_r_max = 2.5;
  int viewpoint_rings = 3;
  double viewpoint_dphi_deg = 15.0; // angular step on a ring, degrees
  double viewpoint_clearance = 0.3; // no occupied or unknown voxel within this of a viewpoint, m
  double sensor_range = 4.5;        // gain: frontier cells within this range, m
  double sensor_hfov_deg = 87.0;    // ... and inside this field of view
  double sensor_vfov_deg = 58.0;
  double yaw_step_deg = 5.0;        // yaws tried per viewpoint
  int min_viewpoint_gain = 10;      // viewpoints seeing fewer frontier cells are dropped
  int max_viewpoints = 10;          // best viewpoints kept per frontier
  double unknown_volume_weight = 10.0;  // a frontier's gain adds this many cells per m^3 of
                                        // unknown space its best viewpoint looks into (band z
                                        // only): a door onto an unexplored room is worth more
                                        // than its doorway's cells (0: FUEL's gain alone)
  // What the camera has seen (CameraCoverage): a 2-D map of known free space at flight height
  // and of the cells the depth camera has looked at; known-but-unseen patches become targets.
  double seen_resolution = 0.25;    // cell size of that map, m
  double seen_range = 4.0;          // a camera ray marks cells up to this range, m (objects are
                                    // detected up to perception.max_range)
  int seen_pixel_stride = 4;        // every n-th depth pixel column / row is walked
  double seen_below = 0.6;          // a ray sees a cell's floor objects where it runs at least
                                    // this far below flight height, m
  int unseen_min_cells = 6;         // smaller unseen patches are no target
  double unseen_patch_size = 3.0;   // unseen patches are cut into tiles of this size, m
  double unseen_view_distance = 1.5;// viewpoints this far (and 1.5x, 2x) from a patch, m
  double unseen_clearance = 0.35;   // viewpoints need known free cells within this, m
  template <class V> void visit(V& v) {
    v.field("band_z_min", band_z_min, -100.0, 100.0, "m");
    v.field("band_z_max", band_z_max, -100.0, 100.0, "m");
    v.field("min_cluster_cells", min_cluster_cells, 1, 1000000, "cells");
    v.field("max_cluster_extent", max_cluster_extent, 0.2, 100.0, "m");
    v.field("remember_known_band", remember_known_band);
    v.field("open_in_visited", open_in_visited);
    v.field("open_in_visited_above", open_in_visited_above, 0.0, 100.0, "m");
    v.field("viewpoint_height", viewpoint_height, -100.0, 100.0, "m");
    v.field("viewpoint_r_min", viewpoint_r_min, 0.0, 20.0, "m");
    v.field("viewpoint_r_max", viewpoint_r_max, 0.0, 20.0, "m");
    v.field("viewpoint_rings", viewpoint_rings, 1, 100, "rings");
    v.field("viewpoint_dphi_deg", viewpoint_dphi_deg, 1.0, 180.0, "degrees");
    v.field("viewpoint_clearance", viewpoint_clearance, 0.0, 2.0, "m");
    v.field("sensor_range", sensor_range, 0.1, 100.0, "m");
    v.field("sensor_hfov_deg", sensor_hfov_deg, 1.0, 360.0, "degrees");
    v.field("sensor_vfov_deg", sensor_vfov_deg, 1.0, 180.0, "degrees");
    v.field("yaw_step_deg", yaw_step_deg, 0.5, 90.0, "degrees");
    v.field("min_viewpoint_gain", min_viewpoint_gain, 0, 1000000, "cells");
    v.field("max_viewpoints", max_viewpoints, 1, 10000, "viewpoints");
    v.field("unknown_volume_weight", unknown_volume_weight, 0.0, 100000.0, "cells per m^3");
    v.field("seen_resolution", seen_resolution, 0.05, 2.0, "m");
    v.field("seen_range", seen_range, 0.2, 50.0, "m");
    v.field("seen_pixel_stride", seen_pixel_stride, 1, 64, "pixels");
    v.field("seen_below", seen_below, 0.0, 10.0, "m");
    v.field("unseen_min_cells", unseen_min_cells, 1, 100000, "cells");
    v.field("unseen_patch_size", unseen_patch_size, 0.5, 50.0, "m");
    v.field("unseen_view_distance", unseen_view_distance, 0.3, 20.0, "m");
    v.field("unseen_clearance", unseen_clearance, 0.0, 2.0, "m");
  }
};

// The flight loop of an exploration / ObjectNav episode (ussnav explore, ussnav eval).
struct EpisodeConfig {
  double max_time_s = 600.0;          // budget: simulated seconds
  double max_distance_m = 0.0;        // budget: metres flown (0 = none)
  double replan_period_s = 1.0;       // re-plan at least this often while flying to a viewpoint
  double goal_tolerance = 0.3;        // a viewpoint is reached within this, m
  double found_radius = 1.0;          // success: within this of the target's box, m (DESIGN.md)
  double found_margin = 0.15;         // approach poses aim this much inside found_radius, m
  int target_min_observations = 3;    // an object counts as found after this many observations
  double goal_similarity = 0.85;      // object label matches the goal at this text cosine
  double blacklist_s = 20.0;          // an unreachable target is skipped for this long, s
  double transit_radius = 3.0;        // an object with no approach pose yet: fly to a graph node this near it, m
  double yaw_weight = 1.0;            // cost = max(path / speed, yaw_weight * yaw / yaw rate)
  std::string tour = "search";        // full: order of the region's targets after its best one: search | distance
  double clearance = 0.4;             // flight paths keep this from mapped obstacles, m
  bool fuse_depth = true;             // the depth camera feeds the grid too (LiDAR blind cone)
  bool end_on_collision = true;       // a collision ends the episode as a failure (DESIGN.md)
  bool close_look = true;             // a frontier still open at its reached viewpoint gets one more
                                      // try from the graph node nearest to it before it is dropped
  bool look_around = true;            // at take-off, turn on the spot (three 120-degree steps) before
                                      // the first plan: the camera sees the start room all round
  bool look_first = true;             // a goal object seen during those turns is approached only
                                      // after them, the nearest of all seen (turning costs no path)
  double look_again_m = 0.0;          // > 0: turn round the same way at a reached viewpoint at least
                                      // this far (in plan) from every spot looked round at; 0 = off
  template <class V> void visit(V& v) {
    v.field("max_time_s", max_time_s, 1.0, 1e6, "s");
    v.field("max_distance_m", max_distance_m, 0.0, 1e6, "m");
    v.field("replan_period_s", replan_period_s, 0.05, 100.0, "s");
    v.field("goal_tolerance", goal_tolerance, 0.01, 5.0, "m");
    v.field("found_radius", found_radius, 0.1, 10.0, "m");
    v.field("found_margin", found_margin, 0.0, 1.0, "m");
    v.field("target_min_observations", target_min_observations, 1, 1000, "observations");
    v.field("goal_similarity", goal_similarity, 0.0, 1.0, "cosine");
    v.field("blacklist_s", blacklist_s, 0.0, 1e4, "s");
    v.field("transit_radius", transit_radius, 0.0, 100.0, "m");
    v.field("yaw_weight", yaw_weight, 0.0, 100.0, "");
    v.choice("tour", tour, {"search", "distance"});
    v.field("clearance", clearance, 0.0, 5.0, "m");
    v.field("fuse_depth", fuse_depth);
    v.field("end_on_collision", end_on_collision);
    v.field("close_look", close_look);
    v.field("look_around", look_around);
    v.field("look_first", look_first);
    v.field("look_again_m", look_again_m, 0.0, 1000.0, "m");
  }
};

// An OpenAI-compatible chat-completions endpoint (reasoning.reasoner: llm). Works with Qwen's
// API (base_url https://dashscope.aliyuncs.com/compatible-mode/v1) and local servers (vLLM,
// Ollama, llama.cpp: http://127.0.0.1:PORT/v1). The key is read from the environment variable
// named by api_key_env at run time, never from a file.
struct LlmConfig {
  std::string base_url = "http://127.0.0.1:8000/v1";
  std::string model = "qwen3-8b";
  std::string api_key_env = "USSNAV_LLM_API_KEY";
  double timeout_s = 20.0;          // per attempt (connect + read)
  int retries = 2;                  // extra attempts after a timeout, 429, 5xx or network error
  double backoff_s = 0.5;           // wait before retry k: backoff_s * 2^(k-1) (429: Retry-After if larger)
  double temperature = 0.0;
  int max_tokens = 512;
  bool json_mode = true;            // request response_format {"type": "json_object"}
  template <class V> void visit(V& v) {
    v.text("base_url", base_url, "http(s)://host[:port]/prefix, /chat/completions is appended");
    v.text("model", model, "model name sent to the server");
    v.text("api_key_env", api_key_env, "environment variable holding the key (may be unset)");
    v.field("timeout_s", timeout_s, 0.05, 600.0, "s");
    v.field("retries", retries, 0, 10, "attempts");
    v.field("backoff_s", backoff_s, 0.0, 60.0, "s");
    v.field("temperature", temperature, 0.0, 2.0, "");
    v.field("max_tokens", max_tokens, 16, 32768, "tokens");
    v.field("json_mode", json_mode);
  }
};

// Coarse-level reasoning (paper Sec. V-B): region semantics and the region to search.
struct ReasoningConfig {
  std::string reasoner = "builtin";   // builtin (offline commonsense) | llm | oracle, oracle-labels (evaluation only: ground truth)
  std::string prompts_dir = "";       // "" = the repository's prompts/
  double label_min_interval_s = 2.0;  // a region is re-labelled at most this often (sim time), s
  int label_queue = 16;               // pending region-label requests; older ones are dropped
  double decision_min_interval_s = 0.0;  // coarse decisions at most this often; 0 = every re-plan
  // builtin/oracle: act on a region's chance only when it is at least this many times the
  // chance of the global-utility region (ChanceRule, reasoning/builtin_reasoner.hpp); 0 = always
  double min_chance_ratio = 1.5;
  // ... and at least this much higher (chances near the floor differ by noise: 0.09 against
  // 0.06 for a bed in two regions with nothing of a bedroom in sight); 0 = the ratio alone
  double min_chance_gap = 0.1;
  // An object seen beyond a region counts for the region of the frontier facing it through
  // space seen free (episode/beyond_objects.hpp), not for the region it was seen from.
  bool beyond_via_frontier = true;
  LlmConfig llm;
  template <class V> void visit(V& v) {
    v.choice("reasoner", reasoner, {"builtin", "llm", "oracle", "oracle-labels"});
    v.text("prompts_dir", prompts_dir, "folder with the prompt files; empty = repository prompts/");
    v.field("label_min_interval_s", label_min_interval_s, 0.0, 1e4, "s");
    v.field("label_queue", label_queue, 1, 10000, "requests");
    v.field("decision_min_interval_s", decision_min_interval_s, 0.0, 1e4, "s");
    v.field("min_chance_ratio", min_chance_ratio, 0.0, 100.0, "x");
    v.field("min_chance_gap", min_chance_gap, 0.0, 1.0, "chance");
    v.field("beyond_via_frontier", beyond_via_frontier);
    v.section("llm", llm);
  }
};

struct Config {
  SimConfig sim;
  MappingConfig mapping;
  SkeletonConfig skeleton;
  PerceptionConfig perception;
  ObjectsConfig objects;
  RegionsConfig regions;
  ExplorationConfig exploration;
  EpisodeConfig episode;
  ReasoningConfig reasoning;
  template <class V> void visit(V& v) {
    v.section("sim", sim);
    v.section("mapping", mapping);
    v.section("skeleton", skeleton);
    v.section("perception", perception);
    v.section("objects", objects);
    v.section("regions", regions);
    v.section("exploration", exploration);
    v.section("episode", episode);
    v.section("reasoning", reasoning);
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
