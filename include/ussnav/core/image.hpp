#pragma once
// A small RGB raster for the pictures every command writes (top-down maps, graphs, worlds).
// Drawing is clipped to the image; PNG output goes through libpng and is written atomically.

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "ussnav/core/types.hpp"

namespace ussnav {

using Rgb = std::array<uint8_t, 3>;

class Image {
 public:
  Image(int width, int height, Rgb fill = {255, 255, 255});
  int width() const { return w_; }
  int height() const { return h_; }
  Rgb at(int x, int y) const;
  void set(int x, int y, Rgb c);
  void blend(int x, int y, Rgb c, double alpha);
  void line(double x0, double y0, double x1, double y1, Rgb c, int thickness = 1);
  void fillRect(int x0, int y0, int x1, int y1, Rgb c, double alpha = 1.0);
  void fillPolygon(const std::vector<Vec2>& pts, Rgb c, double alpha = 1.0);
  void polygonOutline(const std::vector<Vec2>& pts, Rgb c, int thickness = 1);
  void fillCircle(double cx, double cy, double r, Rgb c);
  // 5x7 bitmap text (ASCII; lowercase drawn as capitals), `scale` pixels per font pixel.
  void text(int x, int y, const std::string& s, Rgb c, int scale = 1);
  static int textWidth(const std::string& s, int scale = 1) { return int(s.size()) * 6 * scale; }
  const std::vector<uint8_t>& data() const { return px_; }

 private:
  int w_, h_;
  std::vector<uint8_t> px_;
};

// Encodes to PNG bytes.
std::string encodePng(const Image& img);
// Writes a PNG atomically.
void writePng(const std::filesystem::path& path, const Image& img);

// Maps world x-y (metres) to pixels for top-down pictures: y up in the world is up in the image.
struct TopDownView {
  double min_x = 0, min_y = 0, px_per_m = 20;
  int width = 0, height = 0;
  static TopDownView fit(const Aabb& bounds, double px_per_m, int margin_px = 20, int max_px = 4000);
  Vec2 toPx(const Vec2& p) const;
  Vec2 toPx(const Vec3& p) const { return toPx(Vec2(p.x(), p.y())); }
};

// A distinct colour for index i (golden-angle hue walk), for rooms, regions and objects.
Rgb paletteColor(int i);

}  // namespace ussnav
