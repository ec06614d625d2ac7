#pragma once
// Helpers shared by the importers (private to src/sim/importers): TSV tables and JSON fields
// with errors that name file, line or JSON path; category names; room/object bookkeeping;
// choosing a collision-free start pose.

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "ussnav/sim/importers/import_report.hpp"
#include "ussnav/sim/world.hpp"

namespace ussnav::importers {

// A tab-separated table with one header row. Cells are raw strings; `line` is 1-based.
struct TsvTable {
  std::string file;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::vector<int> lines;
  int column(const std::string& name) const;  // throws InputError when absent
  double number(size_t row, int col) const;   // throws InputError naming file:line and column
  const std::string& cell(size_t row, int col) const;
};
// Reads `path`; every row must have the header's number of columns (trailing empty cells may
// be missing) and the header must contain `required`.
TsvTable readTsv(const std::filesystem::path& path, const std::vector<std::string>& required);

// Typed JSON access; failures throw InputError(file, path, what).
class JsonFields {
 public:
  explicit JsonFields(std::string file) : file_(std::move(file)) {}
  [[noreturn]] void fail(const std::string& path, const std::string& what) const;
  const nlohmann::json& member(const nlohmann::json& obj, const std::string& path, const char* key) const;
  const nlohmann::json& array(const nlohmann::json& obj, const std::string& path, const char* key) const;
  double number(const nlohmann::json& obj, const std::string& path, const char* key) const;
  std::string string(const nlohmann::json& obj, const std::string& path, const char* key) const;
  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

// "DiningTable" -> "dining table", "TVStand" -> "tv stand"; `overrides` maps whole names first.
std::string categoryFromTypeName(const std::string& type, const std::map<std::string, std::string>& overrides = {});

// Reverses `poly` when it is clockwise.
void makeCounterClockwise(std::vector<Vec2>& poly);

// Sets each object's room_id to the room holding its centre; objects outside every room are
// removed and counted in report->dropped_objects with one warning each. Ids become 1..N in order.
void assignRoomsAndDropOutside(World& w, ImportReport* report);

// Distance from p to the nearest wall (as a segment), object box or room edge, in the plane at
// height z; +inf when nothing is near.
double clearanceAt(const World& w, const Vec3& p);
// A start pose at `height` above the floor of the largest room, at the grid point (0.1 m) of
// that room farthest from walls, room edges and objects. Throws InputError when the world has
// no room.
Pose freeStartInLargestRoom(const World& w, double height, const std::string& source);

// `v` with `prec` decimals, for report notes ("1.20").
std::string fmt(double v, int prec = 2);

// Voxel keys (i, j, k) with |i|, |j|, |k| < kVoxelKeyHalf packed into one integer (for sets).
constexpr int kVoxelKeyBits = 21;
constexpr int kVoxelKeyHalf = 1 << (kVoxelKeyBits - 1);
inline uint64_t packVoxelKey(const Vec3i& c) {
  return (uint64_t(c.x() + kVoxelKeyHalf) << (2 * kVoxelKeyBits)) | (uint64_t(c.y() + kVoxelKeyHalf) << kVoxelKeyBits) |
         uint64_t(c.z() + kVoxelKeyHalf);
}
// Sorts voxel keys by (z, y, x), the order the world files list them in.
void sortVoxels(std::vector<Vec3i>& cells);

// A start in a voxel world (cells at origin 0, `res` m): among cells of the 2D projection that
// are free in the band floor+0.3 .. floor+flight+0.6 m and enclosed by occupied cells in all four
// axis directions, those with clearance >= min(best clearance, 1 m); of these the one nearest the
// centroid of the occupied cells. found = false when no free cell exists; enclosed = false when
// no free cell is enclosed (then the clearest free cell anywhere).
struct VoxelStart {
  bool found = false;
  bool enclosed = true;
  Vec2 xy = Vec2::Zero();
  double clearance = 0;  // metres, in the 2D projection
};
VoxelStart chooseVoxelStart(const std::vector<Vec3i>& cells, double res, double floor_z, double flight);

}  // namespace ussnav::importers
