#include "pictures/cairo_painter.h"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <variant>

#include "core/error.h"
#include "io/output_file.h"
#include "pictures/file_names.h"

namespace fosssim {

namespace {

constexpr double kTextMargin = 6.0;   // pixels from the top-left corner
constexpr double kLineSpacing = 1.3;  // line height / font size
/// Surface triangles are painted grown by this many pixels, at most kSeamMiter at a corner.
constexpr double kSeamPixels = 0.5;
constexpr double kSeamMiter = 1.5;

struct SurfaceDeleter {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
struct ContextDeleter {
  void operator()(cairo_t* cr) const { cairo_destroy(cr); }
};
using SurfacePtr = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;
using ContextPtr = std::unique_ptr<cairo_t, ContextDeleter>;

void set_color(cairo_t* cr, const Color& c) { cairo_set_source_rgb(cr, c.r, c.g, c.b); }

void paint_text(cairo_t* cr, const Drawing& drawing) {
  if (drawing.text.empty()) return;
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, drawing.font_size);
  cairo_font_extents_t font;
  cairo_font_extents(cr, &font);
  set_color(cr, drawing.text_color);
  double baseline = kTextMargin + font.ascent;
  for (const std::string& line : drawing.text) {
    cairo_move_to(cr, kTextMargin, baseline);
    cairo_show_text(cr, line.c_str());
    baseline += kLineSpacing * drawing.font_size;
  }
}

void paint_polyline(cairo_t* cr, const Polyline& line) {
  cairo_new_path(cr);
  for (const Point2& p : line.points) cairo_line_to(cr, p.x, p.y);
  cairo_set_line_width(cr, line.width);
  set_color(cr, line.color);
  cairo_stroke(cr);
}

void paint_shape(cairo_t* cr, const Capsule& edge) {
  cairo_move_to(cr, edge.a.x, edge.a.y);
  cairo_line_to(cr, edge.b.x, edge.b.y);
  cairo_set_line_width(cr, 2.0 * edge.radius);
  set_color(cr, edge.color);
  cairo_stroke(cr);
}

void paint_shape(cairo_t* cr, const Disc& disc) {
  cairo_new_path(cr);
  cairo_arc(cr, disc.center.x, disc.center.y, disc.radius, 0.0, 2.0 * std::numbers::pi);
  set_color(cr, disc.color);
  cairo_fill(cr);
}

void paint_shape(cairo_t* cr, const Ring& ring) {
  cairo_new_path(cr);
  cairo_arc(cr, ring.center.x, ring.center.y, ring.radius, 0.0, 2.0 * std::numbers::pi);
  cairo_set_line_width(cr, ring.width);
  set_color(cr, ring.color);
  cairo_stroke(cr);
}

/// Corner `a` of a triangle moved outward so that both its sides move out by kSeamPixels
/// (along the bisector by kSeamPixels / sin(half angle)), but never farther than kSeamMiter.
Point2 grown_corner(const Point2& a, const Point2& b, const Point2& c) {
  const double lb = std::hypot(b.x - a.x, b.y - a.y), lc = std::hypot(c.x - a.x, c.y - a.y);
  if (lb == 0.0 || lc == 0.0) return a;
  const double ux = (b.x - a.x) / lb, uy = (b.y - a.y) / lb;
  const double wx = (c.x - a.x) / lc, wy = (c.y - a.y) / lc;
  const double bx = ux + wx, by = uy + wy, length = std::hypot(bx, by);
  if (length == 0.0) return a;
  const double sin_half = 0.5 * std::hypot(ux - wx, uy - wy);
  const double offset = sin_half > 0.0 ? std::min(kSeamPixels / sin_half, kSeamMiter) : 0.0;
  return {a.x - offset * bx / length, a.y - offset * by / length};
}

/// A surface triangle, filled grown by kSeamPixels so that anti-aliased neighbours overlap
/// instead of letting the background show through their shared side; then its outline.
void paint_shape(cairo_t* cr, const Triangle& triangle) {
  const auto& [a, b, c] = triangle.corners;
  const Point2 ga = grown_corner(a, b, c), gb = grown_corner(b, c, a), gc = grown_corner(c, a, b);
  cairo_move_to(cr, ga.x, ga.y);
  cairo_line_to(cr, gb.x, gb.y);
  cairo_line_to(cr, gc.x, gc.y);
  cairo_close_path(cr);
  set_color(cr, triangle.color);
  cairo_fill(cr);
  if (triangle.outline_width <= 0.0) return;
  cairo_move_to(cr, a.x, a.y);
  cairo_line_to(cr, b.x, b.y);
  cairo_line_to(cr, c.x, c.y);
  cairo_close_path(cr);
  cairo_set_line_width(cr, triangle.outline_width);
  set_color(cr, triangle.outline_color);
  cairo_stroke(cr);
}

void check_status(cairo_status_t status, const std::string& what,
                  ErrorKind kind = ErrorKind::kCannotWrite) {
  if (status != CAIRO_STATUS_SUCCESS) {
    throw Error(kind, what + ": " + cairo_status_to_string(status));
  }
}

/// A copy of an ARGB32 image surface's pixels.
Image copy_pixels(cairo_surface_t* surface) {
  cairo_surface_flush(surface);
  Image image;
  image.width = cairo_image_surface_get_width(surface);
  image.height = cairo_image_surface_get_height(surface);
  image.pixels.resize(static_cast<std::size_t>(image.width) * image.height);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  for (int y = 0; y < image.height; ++y) {
    std::memcpy(&image.pixels[static_cast<std::size_t>(y) * image.width], data + y * stride,
                sizeof(std::uint32_t) * image.width);
  }
  return image;
}

}  // namespace

void paint_drawing(cairo_t* cr, const Drawing& drawing) {
  set_color(cr, drawing.background);
  cairo_paint(cr);

  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  for (const Region& region : drawing.regions) {
    cairo_set_source_rgb(cr, region.color.r, region.color.g, region.color.b);
    cairo_move_to(cr, region.corners[0].x, region.corners[0].y);
    for (std::size_t k = 1; k < region.corners.size(); ++k) {
      cairo_line_to(cr, region.corners[k].x, region.corners[k].y);
    }
    cairo_close_path(cr);
    cairo_fill(cr);
  }
  for (const Polyline& line : drawing.paths) paint_polyline(cr, line);
  for (const Shape& shape : drawing.shapes) {
    std::visit([cr](const auto& s) { paint_shape(cr, s); }, shape);
  }
  for (const Capsule& edge : drawing.edges) paint_shape(cr, edge);
  for (const Disc& disc : drawing.particles) paint_shape(cr, disc);
  for (const Ring& ring : drawing.marks) paint_shape(cr, ring);
  for (const Polyline& line : drawing.guides) paint_polyline(cr, line);
  paint_text(cr, drawing);
}

Image render_image(const Drawing& drawing) {
  SurfacePtr surface(
      cairo_image_surface_create(CAIRO_FORMAT_ARGB32, drawing.width, drawing.height));
  check_status(cairo_surface_status(surface.get()), "cannot create a picture");
  {
    ContextPtr cr(cairo_create(surface.get()));
    paint_drawing(cr.get(), drawing);
  }
  return copy_pixels(surface.get());
}

void write_png(const Image& image, const std::string& path) {
  const int stride = cairo_format_stride_for_width(CAIRO_FORMAT_ARGB32, image.width);
  std::vector<unsigned char> data(static_cast<std::size_t>(stride) * image.height);
  for (int y = 0; y < image.height; ++y) {
    std::memcpy(&data[static_cast<std::size_t>(y) * stride],
                &image.pixels[static_cast<std::size_t>(y) * image.width],
                sizeof(std::uint32_t) * image.width);
  }
  SurfacePtr source(cairo_image_surface_create_for_data(data.data(), CAIRO_FORMAT_ARGB32,
                                                        image.width, image.height, stride));
  write_picture(path, PictureFormat::kPng, image.width, image.height, [&source](cairo_t* cr) {
    cairo_set_source_surface(cr, source.get(), 0, 0);
    cairo_set_operator(cr, CAIRO_OPERATOR_SOURCE);
    cairo_paint(cr);
  });
}

PictureFormat picture_format_for(const std::string& path) {
  return has_extension(path, ".svg") ? PictureFormat::kSvg : PictureFormat::kPng;
}

void write_picture(const std::string& path, PictureFormat format, int width, int height,
                   const std::function<void(cairo_t*)>& paint) {
  const OutputFile output(path);
  const std::string& target = output.write_path();
  const bool svg = format == PictureFormat::kSvg;
  SurfacePtr surface(svg ? cairo_svg_surface_create(target.c_str(), width, height)
                         : cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height));
  cairo_status_t status = cairo_surface_status(surface.get());
  if (status == CAIRO_STATUS_SUCCESS) {
    if (svg) cairo_svg_surface_set_document_unit(surface.get(), CAIRO_SVG_UNIT_PX);
    {
      ContextPtr cr(cairo_create(surface.get()));
      paint(cr.get());
    }
    if (!svg) status = cairo_surface_write_to_png(surface.get(), target.c_str());
    cairo_surface_finish(surface.get());
    if (status == CAIRO_STATUS_SUCCESS) status = cairo_surface_status(surface.get());
  }
  surface.reset();
  if (status != CAIRO_STATUS_SUCCESS) {
    output.discard();
    throw Error(ErrorKind::kCannotWrite,
                "cannot write " + target + ": " + cairo_status_to_string(status));
  }
  output.commit();
}

void write_png(const Drawing& drawing, const std::string& path) {
  write_picture(path, PictureFormat::kPng, drawing.width, drawing.height,
                [&drawing](cairo_t* cr) { paint_drawing(cr, drawing); });
}

void write_svg(const Drawing& drawing, const std::string& path) {
  write_picture(path, PictureFormat::kSvg, drawing.width, drawing.height,
                [&drawing](cairo_t* cr) { paint_drawing(cr, drawing); });
}

Image read_png(const std::string& path) {
  SurfacePtr surface(cairo_image_surface_create_from_png(path.c_str()));
  check_status(cairo_surface_status(surface.get()), "cannot read " + path, ErrorKind::kBadInput);
  SurfacePtr argb(cairo_image_surface_create(CAIRO_FORMAT_ARGB32,
                                             cairo_image_surface_get_width(surface.get()),
                                             cairo_image_surface_get_height(surface.get())));
  {
    ContextPtr cr(cairo_create(argb.get()));
    cairo_set_source_surface(cr.get(), surface.get(), 0, 0);
    cairo_paint(cr.get());
  }
  return copy_pixels(argb.get());
}

}  // namespace fosssim
