#include "ussnav/sim/importers/import.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "ussnav/core/error.hpp"
#include "ussnav/core/io.hpp"

namespace ussnav {

namespace fs = std::filesystem;

const char* importFormatName(ImportFormat f) {
  switch (f) {
    case ImportFormat::kProcthor: return "procthor";
    case ImportFormat::kWebots: return "webots";
    case ImportFormat::kScan: return "scan";
    case ImportFormat::kGazebo: return "gazebo";
  }
  return "?";
}

std::string acceptedImportFormats() {
  return "ProcTHOR house .json (rooms[] with floorPolygon); Webots apartment (its folder, the .wbt, "
         "or rooms_enu.tsv, with rooms_enu.tsv and objects_enu.tsv beside it); AWS RoboMaker Gazebo world (its folder, "
         "the .world or objects.tsv, with objects.tsv and models/ beside it); OctoMap .bt/.ot; PCD .pcd";
}

ImportFormat detectImportFormat(const fs::path& path) {
  const std::string file = path.string();
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(file, "", "no such file or folder");
  if (fs::is_directory(path, ec)) {
    if (fs::exists(path / "rooms_enu.tsv")) return ImportFormat::kWebots;
    if (isGazeboDataset(path)) return ImportFormat::kGazebo;
    throw InputError(file, "", "a folder without rooms_enu.tsv or objects.tsv and a .world; accepted: " + acceptedImportFormats());
  }
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  const std::string name = path.filename().string();
  if (ext == ".bt" || ext == ".ot" || ext == ".pcd") return ImportFormat::kScan;
  if (ext == ".world" || name == "objects.tsv") {
    if (!isGazeboDataset(path))
      throw InputError(file, "", "a Gazebo world needs objects.tsv and a .world file in the same folder");
    return ImportFormat::kGazebo;
  }
  if (ext == ".wbt" || name == "rooms_enu.tsv" || name == "objects_enu.tsv") return ImportFormat::kWebots;
  if (ext == ".json") {
    const nlohmann::json j = readJsonFile(path);
    if (isProcthorHouse(j)) return ImportFormat::kProcthor;
    if (j.is_object() && j.value("format", "") == "ussnav-world")
      throw InputError(file, "format", "already a ussnav world; load it directly instead of importing");
    throw InputError(file, "", "JSON of unknown kind (no rooms[] with floorPolygon); accepted: " + acceptedImportFormats());
  }
  throw InputError(file, "", "unknown format '" + ext + "'; accepted: " + acceptedImportFormats());
}

World importWorld(const fs::path& path, const ImportOptions& opt, ImportReport* report) {
  switch (detectImportFormat(path)) {
    case ImportFormat::kProcthor: return importProcthorHouse(path, opt, report);
    case ImportFormat::kWebots: return importWebotsApartment(path, opt, report);
    case ImportFormat::kScan: return importScan(path, opt, report);
    case ImportFormat::kGazebo: return importGazeboWorld(path, opt, report);
  }
  throw InputError(path.string(), "", "no importer");
}

}  // namespace ussnav
