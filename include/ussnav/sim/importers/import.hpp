#pragma once
// One entry point for the world importers: importWorld(path) picks the loader from the path
// (extension, folder contents) and, for JSON, from the content, then returns a World that
// passes validateWorld. Unknown or malformed input -> InputError naming the file and, for an
// unknown format, the formats that are accepted. Cost: that of the chosen loader.

#include <filesystem>
#include <string>

#include "ussnav/sim/importers/gazebo.hpp"
#include "ussnav/sim/importers/import_report.hpp"
#include "ussnav/sim/importers/procthor.hpp"
#include "ussnav/sim/importers/scan.hpp"
#include "ussnav/sim/importers/webots.hpp"
#include "ussnav/sim/world.hpp"

namespace ussnav {

enum class ImportFormat { kProcthor, kWebots, kScan, kGazebo };

// "procthor", "webots", "scan", "gazebo".
const char* importFormatName(ImportFormat f);
// One line listing what importWorld accepts (used in error messages and --help).
std::string acceptedImportFormats();
// Which loader reads `path`; throws InputError when none does.
ImportFormat detectImportFormat(const std::filesystem::path& path);
World importWorld(const std::filesystem::path& path, const ImportOptions& opt = {}, ImportReport* report = nullptr);

}  // namespace ussnav
