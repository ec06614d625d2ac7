#include "ussnav/core/config.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <set>
#include <sstream>

#include "ussnav/core/error.hpp"

namespace ussnav {

namespace {

std::string join(const std::string& prefix, const std::string& key) {
  return prefix.empty() ? key : prefix + "." + key;
}

// Reads a YAML map into a config struct; records which keys it consumed so that the rest can
// be reported as unknown.
class YamlReader {
 public:
  YamlReader(YAML::Node node, std::string file, std::string prefix)
      : node_(std::move(node)), file_(std::move(file)), prefix_(std::move(prefix)) {}

  template <class T, class L>
  void field(const char* key, T& value, L lo_in, L hi_in, const char* /*doc*/) {
    const T lo = static_cast<T>(lo_in), hi = static_cast<T>(hi_in);
    YAML::Node n = take(key);
    if (!n) return;
    value = convert<T>(n, key);
    if (!(value >= lo && value <= hi)) {
      std::ostringstream s;
      s << "value " << value << " out of range; expected " << lo << " to " << hi;
      throw InputError(file_, join(prefix_, key), s.str());
    }
  }
  void field(const char* key, bool& value) {
    YAML::Node n = take(key);
    if (n) value = convert<bool>(n, key);
  }
  void text(const char* key, std::string& value, const char* /*doc*/) {
    YAML::Node n = take(key);
    if (n) value = convert<std::string>(n, key);
  }
  void choice(const char* key, std::string& value, const std::vector<std::string>& options) {
    YAML::Node n = take(key);
    if (!n) return;
    std::string v = convert<std::string>(n, key);
    bool ok = false;
    std::string list;
    for (const auto& o : options) {
      ok = ok || o == v;
      list += (list.empty() ? "" : "|") + o;
    }
    if (!ok) throw InputError(file_, join(prefix_, key), "'" + v + "' is not one of " + list);
    value = v;
  }
  template <class S>
  void section(const char* key, S& sub) {
    YAML::Node n = take(key);
    if (!n) return;
    if (!n.IsMap())
      throw InputError(file_, join(prefix_, key), "expected a map of settings");
    YamlReader r(n, file_, join(prefix_, key));
    sub.visit(r);
    r.finish();
  }
  void finish() const {
    for (auto it = node_.begin(); it != node_.end(); ++it) {
      const std::string k = it->first.as<std::string>();
      if (!seen_.count(k))
        throw InputError(file_, join(prefix_, k), "unknown key (typo? see configs/default.yaml)");
    }
  }

 private:
  YAML::Node take(const char* key) {
    seen_.insert(key);
    YAML::Node n = node_[key];
    if (!n || n.IsNull()) return YAML::Node(YAML::NodeType::Undefined);
    return n;
  }
  template <class T>
  T convert(const YAML::Node& n, const char* key) const {
    const char* expected = std::is_same_v<T, bool>          ? "true or false"
                           : std::is_same_v<T, int>         ? "an integer"
                           : std::is_same_v<T, double>      ? "a number"
                                                            : "a string";
    if (!n.IsScalar()) throw InputError(file_, join(prefix_, key), std::string("expected ") + expected);
    try {
      T v = n.as<T>();
      if constexpr (std::is_same_v<T, double>) {
        if (!std::isfinite(v)) throw YAML::BadConversion(n.Mark());
      }
      return v;
    } catch (const YAML::BadConversion&) {
      throw InputError(file_, join(prefix_, key),
                       "'" + n.Scalar() + "' has the wrong type; expected " + expected);
    }
  }

  YAML::Node node_;
  std::string file_, prefix_;
  std::set<std::string> seen_;
};

// Emits every field as YAML in declaration order.
class YamlWriter {
 public:
  explicit YamlWriter(YAML::Emitter& out) : out_(out) {}
  template <class T, class L>
  void field(const char* key, T& value, L, L, const char*) {
    out_ << YAML::Key << key << YAML::Value << value;
  }
  void field(const char* key, bool& value) { out_ << YAML::Key << key << YAML::Value << value; }
  void choice(const char* key, std::string& value, const std::vector<std::string>&) {
    out_ << YAML::Key << key << YAML::Value << value;
  }
  void text(const char* key, std::string& value, const char*) {
    out_ << YAML::Key << key << YAML::Value << YAML::DoubleQuoted << value;
  }
  template <class S>
  void section(const char* key, S& sub) {
    out_ << YAML::Key << key << YAML::Value << YAML::BeginMap;
    sub.visit(*this);
    out_ << YAML::EndMap;
  }

 private:
  YAML::Emitter& out_;
};

void applyOverride(YAML::Node root, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set", assignment, "expected key.path=value");
  const std::string path = assignment.substr(0, eq);
  const std::string value = assignment.substr(eq + 1);
  std::vector<std::string> parts;
  std::stringstream ss(path);
  for (std::string p; std::getline(ss, p, '.');) {
    if (p.empty()) throw InputError("--set", path, "empty key segment");
    parts.push_back(p);
  }
  // Walk with explicit node copies: yaml-cpp nodes are handles, so assignment writes through.
  std::vector<YAML::Node> chain{root};
  for (size_t i = 0; i + 1 < parts.size(); ++i) {
    YAML::Node next = chain.back()[parts[i]];
    if (!next.IsDefined() || next.IsNull()) {
      chain.back()[parts[i]] = YAML::Node(YAML::NodeType::Map);
      next = chain.back()[parts[i]];
    }
    chain.push_back(next);
  }
  YAML::Node parsed;
  try {
    parsed = YAML::Load(value);
  } catch (const YAML::Exception&) {
    parsed = YAML::Node(value);
  }
  chain.back()[parts.back()] = parsed;
}

Config readNode(YAML::Node root, const std::string& file) {
  Config cfg;
  if (!root || root.IsNull()) return cfg;
  if (!root.IsMap()) throw InputError(file, "", "expected a YAML map at the top level");
  YamlReader r(root, file, "");
  cfg.visit(r);
  r.finish();
  validateConfig(cfg, file);
  return cfg;
}

}  // namespace

void validateConfig(const Config& c, const std::string& src) {
  if (c.sim.lidar.vmin_deg >= c.sim.lidar.vmax_deg)
    throw InputError(src, "sim.lidar.vmin_deg", "must be below sim.lidar.vmax_deg");
  if (c.sim.camera.min_range >= c.sim.camera.max_range)
    throw InputError(src, "sim.camera.min_range", "must be below sim.camera.max_range");
  if (c.sim.lidar.min_range >= c.sim.lidar.max_range)
    throw InputError(src, "sim.lidar.min_range", "must be below sim.lidar.max_range");
  const auto& g = c.mapping.grid;
  if (g.log_odds_min >= g.occupied_threshold || g.occupied_threshold >= g.log_odds_max)
    throw InputError(src, "mapping.grid.occupied_threshold",
                     "must lie between log_odds_min and log_odds_max");
  for (double s : {g.size_x, g.size_y, g.size_z})
    if (s < 4 * g.resolution)
      throw InputError(src, "mapping.grid.size_*", "window must be at least 4 voxels wide");
  if (c.skeleton.max_radius > 0.5 * std::min(g.size_x, g.size_y))
    throw InputError(src, "skeleton.max_radius", "must fit in half the grid window");
}

Config loadConfig(const std::filesystem::path& path, const std::vector<std::string>& overrides) {
  YAML::Node root;
  const std::string file = path.string();
  try {
    root = YAML::LoadFile(file);
  } catch (const YAML::BadFile&) {
    throw InputError(file, "", "cannot open config file");
  } catch (const YAML::Exception& e) {
    throw InputError(file, "", std::string("malformed YAML: ") + e.what());
  }
  if (!root || root.IsNull()) root = YAML::Node(YAML::NodeType::Map);
  if (!root.IsMap()) throw InputError(file, "", "expected a YAML map at the top level");
  for (const auto& o : overrides) applyOverride(root, o);
  return readNode(root, overrides.empty() ? file : file + " (with --set)");
}

Config defaultConfig(const std::vector<std::string>& overrides) {
  YAML::Node root(YAML::NodeType::Map);
  for (const auto& o : overrides) applyOverride(root, o);
  return readNode(root, "--set");
}

std::string configToYaml(const Config& cfg) {
  YAML::Emitter out;
  out << YAML::BeginMap;
  YamlWriter w(out);
  const_cast<Config&>(cfg).visit(w);
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

std::filesystem::path defaultConfigPath() {
  namespace fs = std::filesystem;
  for (fs::path p : {fs::path("configs/default.yaml"),
                     fs::path(USSNAV_SOURCE_DIR) / "configs/default.yaml"}) {
    std::error_code ec;
    if (fs::exists(p, ec)) return p;
  }
  return {};
}

}  // namespace ussnav
