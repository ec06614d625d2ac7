#include "ussnav/core/image.hpp"

#include <png.h>

#include <algorithm>
#include <cmath>

#include "ussnav/core/error.hpp"
#include "ussnav/core/io.hpp"

namespace ussnav {

namespace {

// 5x7 glyphs, one byte per row, low 5 bits, MSB of those bits is the left column.
struct Glyph { char c; uint8_t rows[7]; };
constexpr Glyph kFont[] = {
    {'A', {14, 17, 17, 31, 17, 17, 17}}, {'B', {30, 17, 17, 30, 17, 17, 30}},
    {'C', {14, 17, 16, 16, 16, 17, 14}}, {'D', {30, 17, 17, 17, 17, 17, 30}},
    {'E', {31, 16, 16, 30, 16, 16, 31}}, {'F', {31, 16, 16, 30, 16, 16, 16}},
    {'G', {14, 17, 16, 23, 17, 17, 15}}, {'H', {17, 17, 17, 31, 17, 17, 17}},
    {'I', {14, 4, 4, 4, 4, 4, 14}},      {'J', {7, 2, 2, 2, 2, 18, 12}},
    {'K', {17, 18, 20, 24, 20, 18, 17}}, {'L', {16, 16, 16, 16, 16, 16, 31}},
    {'M', {17, 27, 21, 21, 17, 17, 17}}, {'N', {17, 17, 25, 21, 19, 17, 17}},
    {'O', {14, 17, 17, 17, 17, 17, 14}}, {'P', {30, 17, 17, 30, 16, 16, 16}},
    {'Q', {14, 17, 17, 17, 21, 18, 13}}, {'R', {30, 17, 17, 30, 20, 18, 17}},
    {'S', {15, 16, 16, 14, 1, 1, 30}},   {'T', {31, 4, 4, 4, 4, 4, 4}},
    {'U', {17, 17, 17, 17, 17, 17, 14}}, {'V', {17, 17, 17, 17, 17, 10, 4}},
    {'W', {17, 17, 17, 21, 21, 21, 10}}, {'X', {17, 17, 10, 4, 10, 17, 17}},
    {'Y', {17, 17, 17, 10, 4, 4, 4}},    {'Z', {31, 1, 2, 4, 8, 16, 31}},
    {'0', {14, 17, 19, 21, 25, 17, 14}}, {'1', {4, 12, 4, 4, 4, 4, 14}},
    {'2', {14, 17, 1, 2, 4, 8, 31}},     {'3', {31, 2, 4, 2, 1, 17, 14}},
    {'4', {2, 6, 10, 18, 31, 2, 2}},     {'5', {31, 16, 30, 1, 1, 17, 14}},
    {'6', {6, 8, 16, 30, 17, 17, 14}},   {'7', {31, 1, 2, 4, 8, 8, 8}},
    {'8', {14, 17, 17, 14, 17, 17, 14}}, {'9', {14, 17, 17, 15, 1, 2, 12}},
    {'-', {0, 0, 0, 31, 0, 0, 0}},       {'_', {0, 0, 0, 0, 0, 0, 31}},
    {'.', {0, 0, 0, 0, 0, 12, 12}},      {':', {0, 12, 12, 0, 12, 12, 0}},
    {'#', {10, 10, 31, 10, 31, 10, 10}}, {'/', {1, 1, 2, 4, 8, 16, 16}},
    {'(', {2, 4, 8, 8, 8, 4, 2}},        {')', {8, 4, 2, 2, 2, 4, 8}},
    {'%', {24, 25, 2, 4, 8, 19, 3}},     {'=', {0, 0, 31, 0, 31, 0, 0}},
    {',', {0, 0, 0, 0, 12, 4, 8}},       {'+', {0, 4, 4, 31, 4, 4, 0}},
    {'\'', {12, 4, 8, 0, 0, 0, 0}},
};

const Glyph* findGlyph(char c) {
  if (c >= 'a' && c <= 'z') c = char(c - 'a' + 'A');
  for (const auto& g : kFont)
    if (g.c == c) return &g;
  return nullptr;
}

}  // namespace

Image::Image(int width, int height, Rgb fill)
    : w_(std::max(1, width)), h_(std::max(1, height)), px_(size_t(w_) * h_ * 3) {
  for (size_t i = 0; i < px_.size(); i += 3) {
    px_[i] = fill[0];
    px_[i + 1] = fill[1];
    px_[i + 2] = fill[2];
  }
}

Rgb Image::at(int x, int y) const {
  if (x < 0 || y < 0 || x >= w_ || y >= h_) return {0, 0, 0};
  const size_t i = (size_t(y) * w_ + x) * 3;
  return {px_[i], px_[i + 1], px_[i + 2]};
}

void Image::set(int x, int y, Rgb c) {
  if (x < 0 || y < 0 || x >= w_ || y >= h_) return;
  const size_t i = (size_t(y) * w_ + x) * 3;
  px_[i] = c[0];
  px_[i + 1] = c[1];
  px_[i + 2] = c[2];
}

void Image::blend(int x, int y, Rgb c, double a) {
  if (x < 0 || y < 0 || x >= w_ || y >= h_) return;
  const size_t i = (size_t(y) * w_ + x) * 3;
  for (int k = 0; k < 3; ++k)
    px_[i + k] = uint8_t(std::lround((1 - a) * px_[i + k] + a * c[k]));
}

void Image::line(double x0, double y0, double x1, double y1, Rgb c, int thickness) {
  const double len = std::hypot(x1 - x0, y1 - y0);
  const int steps = std::max(1, int(std::ceil(len * 1.5)));
  const int r = thickness / 2;
  for (int s = 0; s <= steps; ++s) {
    const double t = double(s) / steps;
    const int x = int(std::lround(x0 + t * (x1 - x0))), y = int(std::lround(y0 + t * (y1 - y0)));
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx) set(x + dx, y + dy, c);
  }
}

void Image::fillRect(int x0, int y0, int x1, int y1, Rgb c, double alpha) {
  for (int y = std::max(0, std::min(y0, y1)); y <= std::min(h_ - 1, std::max(y0, y1)); ++y)
    for (int x = std::max(0, std::min(x0, x1)); x <= std::min(w_ - 1, std::max(x0, x1)); ++x)
      alpha >= 1.0 ? set(x, y, c) : blend(x, y, c, alpha);
}

void Image::fillPolygon(const std::vector<Vec2>& pts, Rgb c, double alpha) {
  if (pts.size() < 3) return;
  double ymin = pts[0].y(), ymax = ymin;
  for (const auto& p : pts) ymin = std::min(ymin, p.y()), ymax = std::max(ymax, p.y());
  std::vector<double> xs;
  for (int y = std::max(0, int(std::floor(ymin))); y <= std::min(h_ - 1, int(std::ceil(ymax))); ++y) {
    const double yc = y + 0.5;
    xs.clear();
    for (size_t i = 0; i < pts.size(); ++i) {
      const Vec2& a = pts[i];
      const Vec2& b = pts[(i + 1) % pts.size()];
      if ((a.y() <= yc) != (b.y() <= yc))
        xs.push_back(a.x() + (yc - a.y()) / (b.y() - a.y()) * (b.x() - a.x()));
    }
    std::sort(xs.begin(), xs.end());
    for (size_t i = 0; i + 1 < xs.size(); i += 2)
      for (int x = std::max(0, int(std::ceil(xs[i] - 0.5))); x <= std::min(w_ - 1, int(std::floor(xs[i + 1] - 0.5))); ++x)
        alpha >= 1.0 ? set(x, y, c) : blend(x, y, c, alpha);
  }
}

void Image::polygonOutline(const std::vector<Vec2>& pts, Rgb c, int thickness) {
  for (size_t i = 0; i < pts.size(); ++i) {
    const Vec2& a = pts[i];
    const Vec2& b = pts[(i + 1) % pts.size()];
    line(a.x(), a.y(), b.x(), b.y(), c, thickness);
  }
}

void Image::fillCircle(double cx, double cy, double r, Rgb c) {
  for (int y = int(std::floor(cy - r)); y <= int(std::ceil(cy + r)); ++y)
    for (int x = int(std::floor(cx - r)); x <= int(std::ceil(cx + r)); ++x)
      if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r) set(x, y, c);
}

void Image::text(int x, int y, const std::string& s, Rgb c, int scale) {
  int cx = x;
  for (char ch : s) {
    if (const Glyph* g = findGlyph(ch)) {
      for (int row = 0; row < 7; ++row)
        for (int col = 0; col < 5; ++col)
          if (g->rows[row] & (1 << (4 - col)))
            fillRect(cx + col * scale, y + row * scale, cx + (col + 1) * scale - 1,
                     y + (row + 1) * scale - 1, c);
    }
    cx += 6 * scale;
  }
}

namespace {
void pngWrite(png_structp png, png_bytep data, png_size_t len) {
  auto* out = static_cast<std::string*>(png_get_io_ptr(png));
  out->append(reinterpret_cast<const char*>(data), len);
}
void pngFlush(png_structp) {}
}  // namespace

std::string encodePng(const Image& img) {
  std::string out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) throw std::runtime_error("libpng: out of memory");
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error("libpng: encoding failed");
  }
  png_set_write_fn(png, &out, pngWrite, pngFlush);
  png_set_IHDR(png, info, img.width(), img.height(), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  const auto& d = img.data();
  for (int y = 0; y < img.height(); ++y)
    png_write_row(png, const_cast<png_bytep>(d.data() + size_t(y) * img.width() * 3));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return out;
}

void writePng(const std::filesystem::path& path, const Image& img) {
  writeFileAtomic(path, encodePng(img));
}

TopDownView TopDownView::fit(const Aabb& b, double px_per_m, int margin, int max_px) {
  TopDownView v;
  const Vec3 size = b.size();
  const double longest = std::max({size.x(), size.y(), 1.0});
  v.px_per_m = std::min(px_per_m, double(max_px - 2 * margin) / longest);
  v.min_x = b.empty() ? 0 : b.min.x() - margin / v.px_per_m;
  v.min_y = b.empty() ? 0 : b.min.y() - margin / v.px_per_m;
  v.width = int(std::ceil(size.x() * v.px_per_m)) + 2 * margin;
  v.height = int(std::ceil(size.y() * v.px_per_m)) + 2 * margin;
  return v;
}

Vec2 TopDownView::toPx(const Vec2& p) const {
  return Vec2((p.x() - min_x) * px_per_m, height - 1 - (p.y() - min_y) * px_per_m);
}

Rgb paletteColor(int i) {
  const double h = std::fmod(i * 137.508, 360.0) / 60.0;
  const double s = 0.55, v = 0.92;
  const double c = v * s, x = c * (1 - std::fabs(std::fmod(h, 2.0) - 1)), m = v - c;
  double r = 0, g = 0, bl = 0;
  switch (int(h)) {
    case 0: r = c, g = x; break;
    case 1: r = x, g = c; break;
    case 2: g = c, bl = x; break;
    case 3: g = x, bl = c; break;
    case 4: r = x, bl = c; break;
    default: r = c, bl = x; break;
  }
  return {uint8_t((r + m) * 255), uint8_t((g + m) * 255), uint8_t((bl + m) * 255)};
}

}  // namespace ussnav
