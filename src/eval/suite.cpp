#include "ussnav/eval/suite.hpp"

#include <set>
#include <yaml-cpp/yaml.h>

#include "ussnav/core/error.hpp"
#include "ussnav/sim/importers/import.hpp"
#include "ussnav/sim/world_io.hpp"

namespace ussnav {

namespace {

std::vector<std::string> stringList(const YAML::Node& n, const std::string& file, const std::string& field) {
  if (!n.IsSequence()) throw InputError(file, field, "expected a list of strings");
  std::vector<std::string> out;
  for (size_t i = 0; i < n.size(); ++i) {
    if (!n[i].IsScalar() || n[i].as<std::string>().empty())
      throw InputError(file, field + "[" + std::to_string(i) + "]", "expected a non-empty string");
    out.push_back(n[i].as<std::string>());
  }
  return out;
}

template <class T>
T scalar(const YAML::Node& n, const std::string& file, const std::string& field, const char* what) {
  try {
    return n.as<T>();
  } catch (const YAML::Exception&) {
    throw InputError(file, field, std::string("expected ") + what);
  }
}

void checkKeys(const YAML::Node& n, const std::set<std::string>& allowed, const std::string& file,
               const std::string& prefix) {
  for (auto it = n.begin(); it != n.end(); ++it) {
    const std::string k = it->first.as<std::string>();
    if (!allowed.count(k)) {
      std::string list;
      for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
      throw InputError(file, prefix + k, "unknown key (expected one of: " + list + ")");
    }
  }
}

}  // namespace

Suite loadSuite(const std::filesystem::path& path) {
  const std::string file = path.string();
  YAML::Node root;
  try {
    root = YAML::LoadFile(file);
  } catch (const YAML::BadFile&) {
    throw InputError(file, "", "cannot read the suite file");
  } catch (const YAML::Exception& e) {
    throw InputError(file, "", std::string("not valid YAML: ") + e.what());
  }
  if (!root.IsMap()) throw InputError(file, "", "expected a mapping with worlds, goals and seeds");
  checkKeys(root, {"name", "worlds", "goals", "seeds", "max_time_s"}, file, "");
  Suite s;
  s.name = root["name"] ? scalar<std::string>(root["name"], file, "name", "a string") : path.stem().string();
  if (root["goals"]) s.goals = stringList(root["goals"], file, "goals");
  if (root["seeds"]) {
    if (!root["seeds"].IsSequence() || root["seeds"].size() == 0) throw InputError(file, "seeds", "expected a non-empty list of integers");
    s.seeds.clear();
    for (size_t i = 0; i < root["seeds"].size(); ++i)
      s.seeds.push_back(scalar<uint64_t>(root["seeds"][i], file, "seeds[" + std::to_string(i) + "]", "a non-negative integer"));
  }
  if (root["max_time_s"]) {
    const double t = scalar<double>(root["max_time_s"], file, "max_time_s", "a number of seconds");
    if (!(t > 0)) throw InputError(file, "max_time_s", "expected a positive number of seconds");
    s.max_time_s = t;
  }
  const YAML::Node worlds = root["worlds"];
  if (!worlds || !worlds.IsSequence() || worlds.size() == 0) throw InputError(file, "worlds", "expected a non-empty list");
  const std::filesystem::path base = path.parent_path();
  std::set<std::string> names;
  for (size_t i = 0; i < worlds.size(); ++i) {
    const std::string f = "worlds[" + std::to_string(i) + "]";
    const YAML::Node w = worlds[i];
    if (!w.IsMap()) throw InputError(file, f, "expected a mapping with one of generate, file, import");
    checkKeys(w, {"name", "generate", "file", "import", "goals", "start"}, file, f + ".");
    SuiteWorld sw;
    const int kinds = int(bool(w["generate"])) + int(bool(w["file"])) + int(bool(w["import"]));
    if (kinds != 1) throw InputError(file, f, "expected exactly one of generate, file, import");
    if (w["generate"]) {
      const YAML::Node g = w["generate"];
      if (!g.IsMap()) throw InputError(file, f + ".generate", "expected {style, seed, rooms}");
      checkKeys(g, {"style", "seed", "rooms"}, file, f + ".generate.");
      sw.kind = SuiteWorld::Kind::Generate;
      sw.generate.style = g["style"] ? scalar<std::string>(g["style"], file, f + ".generate.style", "office or apartment") : "office";
      if (sw.generate.style != "office" && sw.generate.style != "apartment")
        throw InputError(file, f + ".generate.style", "expected office or apartment");
      sw.generate.seed = g["seed"] ? scalar<uint64_t>(g["seed"], file, f + ".generate.seed", "an integer") : 1;
      sw.generate.target_rooms = g["rooms"] ? scalar<int>(g["rooms"], file, f + ".generate.rooms", "an integer") : 0;
      if (sw.generate.target_rooms != 0 &&
          (sw.generate.target_rooms < kMinGeneratedRooms || sw.generate.target_rooms > kMaxGeneratedRooms))
        throw InputError(file, f + ".generate.rooms",
                         "expected 0 (any) or " + std::to_string(kMinGeneratedRooms) + ".." +
                             std::to_string(kMaxGeneratedRooms) + ", got " + std::to_string(sw.generate.target_rooms));
      sw.name = sw.generate.style + "-" + std::to_string(sw.generate.seed) +
                (sw.generate.target_rooms ? "-r" + std::to_string(sw.generate.target_rooms) : "");
    } else {
      const bool is_file = bool(w["file"]);
      sw.kind = is_file ? SuiteWorld::Kind::File : SuiteWorld::Kind::Import;
      const std::string key = is_file ? "file" : "import";
      const std::filesystem::path p = scalar<std::string>(w[key], file, f + "." + key, "a path");
      sw.path = p.is_absolute() ? p : base / p;
      sw.name = sw.path.stem().string();
    }
    if (w["name"]) sw.name = scalar<std::string>(w["name"], file, f + ".name", "a string");
    if (w["goals"]) sw.goals = stringList(w["goals"], file, f + ".goals");
    if (w["start"]) {
      const YAML::Node st = w["start"];
      if (!st.IsSequence() || (st.size() != 3 && st.size() != 4))
        throw InputError(file, f + ".start", "expected [x, y, z] or [x, y, z, yaw]");
      Pose pose;
      pose.position = Vec3(st[0].as<double>(), st[1].as<double>(), st[2].as<double>());
      if (st.size() == 4) pose.yaw = st[3].as<double>();
      sw.start = pose;
    }
    if (!names.insert(sw.name).second) throw InputError(file, f + ".name", "duplicate world name '" + sw.name + "'");
    s.worlds.push_back(std::move(sw));
  }
  if (s.goals.empty())
    for (size_t i = 0; i < s.worlds.size(); ++i)
      if (s.worlds[i].goals.empty())
        throw InputError(file, "goals", "expected a goal list (or goals on every world)");
  return s;
}

World materializeWorld(const SuiteWorld& w) {
  switch (w.kind) {
    case SuiteWorld::Kind::Generate:
      return generateWorld(w.generate);
    case SuiteWorld::Kind::File:
      return loadWorld(w.path);
    case SuiteWorld::Kind::Import:
      return importWorld(w.path);
  }
  return World{};
}

}  // namespace ussnav
