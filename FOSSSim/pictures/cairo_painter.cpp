#include "pictures/cairo_painter.h"


#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <variant>

#include "core/error.h"
#include "io/output_file.h"
#include "pictures/cairo_library.h"
#include "pictures/file_names.h"

namespace fosssim {

void set_color(cairo_t* cr, const Color& c) { cairo().set_source_rgb(cr, c.r, c.g, c.b); }

namespace {

constexpr double kTextMargin = 6.0;   // pixels from the top-left corner
constexpr double kLineSpacing = 1.3;  // line height / font size
/// Surface triangles are painted grown by this many pixels, at most kSeamMiter at a corner.
constexpr double kSeamPixels = 0.5;
constexpr double kSeamMiter = 1.5;

struct SurfaceDeleter {
  void operator()(cairo_surface_t* s) const { cairo().surface_destroy(s); }
};
struct ContextDeleter {
  void operator()(cairo_t* cr) const { cairo().destroy(cr); }
};
using SurfacePtr = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;
using ContextPtr = std::unique_ptr<cairo_t, ContextDeleter>;

void paint_text(cairo_t* cr, const Drawing& drawing) {
  if (drawing.text.empty()) return;
  cairo().select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo().set_font_size(cr, drawing.font_size);
  cairo_font_extents_t font;
  cairo().font_extents(cr, &font);
  set_color(cr, drawing.text_color);
  double baseline = kTextMargin + font.ascent;
  for (const std::string& line : drawing.text) {
    cairo().move_to(cr, kTextMargin, baseline);
    cairo().show_text(cr, line.c_str());
    baseline += kLineSpacing * drawing.font_size;
  }
}

// ---- Sizes Cairo can draw ---------------------------------------------------------------------
// Cairo keeps coordinates in 24.8 fixed point and flattens arcs into segments: a radius of 1e300
// pixels or a point at 1e12 (a tiny viewport, a huge particle radius, --view 0,0,1e-308) makes
// it overflow or loop for minutes over gigabytes. Shapes are therefore brought within reach
// first: coordinates beyond kReach pixels from the picture's centre are clipped away (exactly:
// what is clipped lies far outside the picture), and a circle wider than kMaxRadius is replaced
// by one of that radius touching the same point nearest the picture (off by less than
// size² / (2 kMaxRadius), a fraction of a pixel at 8192 pixels). Non-finite shapes are skipped.

constexpr double kReach = 1e6;      // pixels from the picture's centre
constexpr double kMaxRadius = 1e5;  // pixels, for circles and line widths

/// The picture's centre and half diagonal, in pixels.
struct Canvas {
  Point2 centre;
  double half_diagonal;
};

Canvas canvas_of(cairo_t* cr) {
  double x1 = 0, y1 = 0, x2 = 0, y2 = 0;
  cairo().clip_extents(cr, &x1, &y1, &x2, &y2);
  return {{0.5 * (x1 + x2), 0.5 * (y1 + y2)}, 0.5 * std::hypot(x2 - x1, y2 - y1)};
}

bool finite(const Point2& p) { return std::isfinite(p.x) && std::isfinite(p.y); }

bool within_reach(const Point2& p, const Canvas& canvas) {
  return std::abs(p.x - canvas.centre.x) <= kReach && std::abs(p.y - canvas.centre.y) <= kReach;
}

/// What to draw of a circle of `radius` around `centre` whose drawing reaches `spread` pixels
/// beyond it (half a stroke width): nothing, the whole picture (a disc covering it), or a circle
/// within reach.
struct FittedCircle {
  enum { kNothing, kEverything, kCircle } what = kNothing;
  Point2 centre;
  double radius = 0.0;
};

FittedCircle fit_circle(const Point2& centre, double radius, double spread, const Canvas& canvas,
                        bool filled) {
  if (!finite(centre) || !std::isfinite(radius) || !std::isfinite(spread)) return {};
  if (radius <= kMaxRadius && within_reach(centre, canvas)) {
    return {FittedCircle::kCircle, centre, radius};
  }
  const double dx = centre.x - canvas.centre.x, dy = centre.y - canvas.centre.y;
  const double distance = std::hypot(dx, dy);
  if (!std::isfinite(distance)) return {};
  const double outside = distance - radius;  // signed distance of the canvas centre to the rim
  const double reach = canvas.half_diagonal + spread;
  if (outside > reach) return {};
  if (-outside > reach)
    return filled ? FittedCircle{FittedCircle::kEverything, {}, 0.0} : FittedCircle{};
  const double ux = distance > 0.0 ? dx / distance : 1.0, uy = distance > 0.0 ? dy / distance : 0.0;
  const double along = outside + kMaxRadius;
  return {FittedCircle::kCircle,
          {canvas.centre.x + ux * along, canvas.centre.y + uy * along},
          kMaxRadius};
}

/// The point of segment p-q where coordinate `axis` equals `bound` (p and q on either side).
/// The other coordinate is interpolated from the clipped one, which stays exact however far
/// the ends are (a parameter along the segment would lose the picture's pixels in rounding).
Point2 crossing(const Point2& p, const Point2& q, int axis, double bound) {
  if (axis == 0) return {bound, p.y + (bound - p.x) * ((q.y - p.y) / (q.x - p.x))};
  return {p.x + (bound - p.y) * ((q.x - p.x) / (q.y - p.y)), bound};
}

/// The four sides of the square of half side kReach around the canvas centre: coordinate
/// `axis` times `side` at most `bound`.
struct Side {
  int axis;
  double side, bound;
  bool inside(const Point2& p) const { return side * (axis == 0 ? p.x : p.y) <= side * bound; }
};

std::array<Side, 4> sides_of(const Canvas& canvas) {
  return {{{0, -1.0, canvas.centre.x - kReach},
           {0, 1.0, canvas.centre.x + kReach},
           {1, -1.0, canvas.centre.y - kReach},
           {1, 1.0, canvas.centre.y + kReach}}};
}

/// The part of segment a-b within the square of half side kReach around the canvas centre;
/// false when none of it is.
bool clip_segment(Point2& a, Point2& b, const Canvas& canvas) {
  for (const Side& side : sides_of(canvas)) {
    const bool a_in = side.inside(a), b_in = side.inside(b);
    if (!a_in && !b_in) return false;
    if (!a_in) a = crossing(a, b, side.axis, side.bound);
    if (!b_in) b = crossing(a, b, side.axis, side.bound);
  }
  return finite(a) && finite(b);
}

/// The polygon clipped to the square of half side kReach around the canvas centre
/// (Sutherland-Hodgman); empty when nothing of it is inside or a corner is not finite.
std::vector<Point2> clip_polygon(const std::vector<Point2>& corners, const Canvas& canvas) {
  for (const Point2& p : corners)
    if (!finite(p)) return {};
  std::vector<Point2> out = corners;
  for (const Side& side : sides_of(canvas)) {
    std::vector<Point2> kept;
    for (std::size_t k = 0; k < out.size(); ++k) {
      const Point2& p = out[k];
      const Point2& q = out[(k + 1) % out.size()];
      const bool p_in = side.inside(p), q_in = side.inside(q);
      if (p_in) kept.push_back(p);
      if (p_in != q_in) kept.push_back(crossing(p, q, side.axis, side.bound));
    }
    out = std::move(kept);
    if (out.empty()) return out;
  }
  for (const Point2& p : out)
    if (!finite(p)) return {};
  return out;
}

bool all_within_reach(const std::vector<Point2>& points, const Canvas& canvas) {
  for (const Point2& p : points)
    if (!finite(p) || !within_reach(p, canvas)) return false;
  return true;
}

/// A polygon's path, clipped when a corner is out of reach; false when nothing is left.
bool polygon_path(cairo_t* cr, const std::vector<Point2>& corners) {
  const Canvas canvas = canvas_of(cr);
  const std::vector<Point2> clipped =
      all_within_reach(corners, canvas) ? corners : clip_polygon(corners, canvas);
  cairo().new_path(cr);
  if (clipped.size() < 3) return false;
  for (const Point2& p : clipped) cairo().line_to(cr, p.x, p.y);
  cairo().close_path(cr);
  return true;
}

double line_width(double width) {
  return std::isfinite(width) ? std::clamp(width, 0.0, 2.0 * kMaxRadius) : 0.0;
}

void paint_polyline(cairo_t* cr, const Polyline& line) {
  const Canvas canvas = canvas_of(cr);
  cairo().new_path(cr);
  if (all_within_reach(line.points, canvas)) {
    for (const Point2& p : line.points) cairo().line_to(cr, p.x, p.y);
  } else {
    for (std::size_t k = 0; k + 1 < line.points.size(); ++k) {
      Point2 a = line.points[k], b = line.points[k + 1];
      if (!finite(a) || !finite(b) || !clip_segment(a, b, canvas)) continue;
      cairo().move_to(cr, a.x, a.y);
      cairo().line_to(cr, b.x, b.y);
    }
  }
  cairo().set_line_width(cr, line_width(line.width));
  set_color(cr, line.color);
  cairo().stroke(cr);
}

void paint_circle(cairo_t* cr, const Point2& centre, double radius, double stroke,
                  const Color& color) {
  const bool filled = stroke <= 0.0;
  const FittedCircle circle =
      fit_circle(centre, radius, filled ? 0.0 : 0.5 * stroke, canvas_of(cr), filled);
  if (circle.what == FittedCircle::kNothing) return;
  set_color(cr, color);
  if (circle.what == FittedCircle::kEverything) {
    cairo().paint(cr);
    return;
  }
  cairo().new_path(cr);
  cairo().arc(cr, circle.centre.x, circle.centre.y, circle.radius, 0.0, 2.0 * std::numbers::pi);
  if (filled) {
    cairo().fill(cr);
  } else {
    cairo().set_line_width(cr, line_width(stroke));
    cairo().stroke(cr);
  }
}

void paint_shape(cairo_t* cr, const Capsule& edge) {
  const Canvas canvas = canvas_of(cr);
  Point2 a = edge.a, b = edge.b;
  if (!finite(a) || !finite(b) || !std::isfinite(edge.radius)) return;
  if (edge.radius > kMaxRadius) {
    // A very wide edge: near the picture its rim is that of the disc around the segment's point
    // nearest the picture's centre.
    const double dx = b.x - a.x, dy = b.y - a.y, length2 = dx * dx + dy * dy;
    double t = length2 > 0.0
                   ? ((canvas.centre.x - a.x) * dx + (canvas.centre.y - a.y) * dy) / length2
                   : 0.0;
    t = std::isfinite(t) ? std::clamp(t, 0.0, 1.0) : 0.0;
    paint_circle(cr, {a.x + t * dx, a.y + t * dy}, edge.radius, 0.0, edge.color);
    return;
  }
  if ((!within_reach(a, canvas) || !within_reach(b, canvas)) && !clip_segment(a, b, canvas)) {
    return;
  }
  cairo().move_to(cr, a.x, a.y);
  cairo().line_to(cr, b.x, b.y);
  cairo().set_line_width(cr, line_width(2.0 * edge.radius));
  set_color(cr, edge.color);
  cairo().stroke(cr);
}

void paint_shape(cairo_t* cr, const Disc& disc) {
  paint_circle(cr, disc.center, disc.radius, 0.0, disc.color);
}

void paint_shape(cairo_t* cr, const Ring& ring) {
  if (!(ring.width > 0.0)) return;
  paint_circle(cr, ring.center, ring.radius, ring.width, ring.color);
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
  if (!polygon_path(cr, {ga, gb, gc})) return;
  set_color(cr, triangle.color);
  cairo().fill(cr);
  if (triangle.outline_width <= 0.0) return;
  if (!polygon_path(cr, {a, b, c})) return;
  cairo().set_line_width(cr, line_width(triangle.outline_width));
  set_color(cr, triangle.outline_color);
  cairo().stroke(cr);
}

void check_status(cairo_status_t status, const std::string& what,
                  ErrorKind kind = ErrorKind::kCannotWrite) {
  if (status != CAIRO_STATUS_SUCCESS) {
    throw Error(kind, what + ": " + cairo().status_to_string(status));
  }
}

/// A copy of an ARGB32 image surface's pixels.
Image copy_pixels(cairo_surface_t* surface) {
  cairo().surface_flush(surface);
  Image image;
  image.width = cairo().image_surface_get_width(surface);
  image.height = cairo().image_surface_get_height(surface);
  image.pixels.resize(static_cast<std::size_t>(image.width) * image.height);
  const unsigned char* data = cairo().image_surface_get_data(surface);
  const int stride = cairo().image_surface_get_stride(surface);
  for (int y = 0; y < image.height; ++y) {
    std::memcpy(&image.pixels[static_cast<std::size_t>(y) * image.width], data + y * stride,
                sizeof(std::uint32_t) * image.width);
  }
  return image;
}

}  // namespace

void paint_drawing(cairo_t* cr, const Drawing& drawing) {
  set_color(cr, drawing.background);
  cairo().paint(cr);

  cairo().set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo().set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  for (const Region& region : drawing.regions) {
    cairo().set_source_rgb(cr, region.color.r, region.color.g, region.color.b);
    if (polygon_path(cr, region.corners)) cairo().fill(cr);
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
      cairo().image_surface_create(CAIRO_FORMAT_ARGB32, drawing.width, drawing.height));
  check_status(cairo().surface_status(surface.get()), "cannot create a picture");
  {
    ContextPtr cr(cairo().create(surface.get()));
    paint_drawing(cr.get(), drawing);
  }
  return copy_pixels(surface.get());
}

void write_png(const Image& image, const std::string& path) {
  const int stride = cairo().format_stride_for_width(CAIRO_FORMAT_ARGB32, image.width);
  std::vector<unsigned char> data(static_cast<std::size_t>(stride) * image.height);
  for (int y = 0; y < image.height; ++y) {
    std::memcpy(&data[static_cast<std::size_t>(y) * stride],
                &image.pixels[static_cast<std::size_t>(y) * image.width],
                sizeof(std::uint32_t) * image.width);
  }
  SurfacePtr source(cairo().image_surface_create_for_data(data.data(), CAIRO_FORMAT_ARGB32,
                                                        image.width, image.height, stride));
  write_picture(path, PictureFormat::kPng, image.width, image.height, [&source](cairo_t* cr) {
    cairo().set_source_surface(cr, source.get(), 0, 0);
    cairo().set_operator(cr, CAIRO_OPERATOR_SOURCE);
    cairo().paint(cr);
  });
}

PictureFormat picture_format_for(const std::string& path) {
  return has_extension(path, ".svg") ? PictureFormat::kSvg : PictureFormat::kPng;
}

namespace {
/// Cairo's write callback: the bytes go to the output's descriptor.
cairo_status_t write_to_output(void* closure, const unsigned char* data, unsigned int length) {
  const int fd = static_cast<const OutputFile*>(closure)->descriptor();
  return write_all(fd, data, length) ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}
}  // namespace

void write_picture(const std::string& path, PictureFormat format, int width, int height,
                   const std::function<void(cairo_t*)>& paint) {
  OutputFile output(path);
  const bool svg = format == PictureFormat::kSvg;
  int write_error = 0;
  SurfacePtr surface(
      svg ? cairo().svg_surface_create_for_stream(write_to_output, &output, width, height)
          : cairo().image_surface_create(CAIRO_FORMAT_ARGB32, width, height));
  cairo_status_t status = cairo().surface_status(surface.get());
  if (status == CAIRO_STATUS_SUCCESS) {
    if (svg) cairo().svg_surface_set_document_unit(surface.get(), CAIRO_SVG_UNIT_PX);
    {
      ContextPtr cr(cairo().create(surface.get()));
      paint(cr.get());
    }
    errno = 0;
    if (!svg) status = cairo().surface_write_to_png_stream(surface.get(), write_to_output, &output);
    cairo().surface_finish(surface.get());
    if (status == CAIRO_STATUS_SUCCESS) status = cairo().surface_status(surface.get());
    write_error = errno;
  }
  surface.reset();
  if (status != CAIRO_STATUS_SUCCESS) {
    output.discard();
    const std::string why = status == CAIRO_STATUS_WRITE_ERROR && write_error != 0
                                ? std::strerror(write_error)
                                : cairo().status_to_string(status);
    throw Error(ErrorKind::kCannotWrite, "cannot write " + path + ": " + why);
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
  SurfacePtr surface(cairo().image_surface_create_from_png(path.c_str()));
  check_status(cairo().surface_status(surface.get()), "cannot read " + path, ErrorKind::kBadInput);
  SurfacePtr argb(cairo().image_surface_create(CAIRO_FORMAT_ARGB32,
                                             cairo().image_surface_get_width(surface.get()),
                                             cairo().image_surface_get_height(surface.get())));
  {
    ContextPtr cr(cairo().create(argb.get()));
    cairo().set_source_surface(cr.get(), surface.get(), 0, 0);
    cairo().paint(cr.get());
  }
  return copy_pixels(argb.get());
}

}  // namespace fosssim
