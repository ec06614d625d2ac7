#pragma once
// Webots "complete apartment" -> World, from the derived rooms_enu.tsv (labelled floor patches)
// and objects_enu.tsv (nodes with ENU poses) beside the .wbt; the .wbt itself is not parsed.
// Wall, Window and Door boxes become walls (doors get openings and Door entries), patches become
// rooms (overlaps split evenly, patches cut where walls cross them fully, the outdoor GARDEN
// dropped), open boundaries between rooms become doorless Doors, furniture gets nominal PROTO
// sizes from a small table. Linear in the number of nodes times walls (a few hundred).

#include <filesystem>

#include "ussnav/sim/importers/import_report.hpp"
#include "ussnav/sim/world.hpp"

namespace ussnav {

// `path`: the apartment folder, the .wbt file or rooms_enu.tsv (the other TSV is found beside).
World importWebotsApartment(const std::filesystem::path& path, const ImportOptions& opt = {},
                            ImportReport* report = nullptr);

}  // namespace ussnav
