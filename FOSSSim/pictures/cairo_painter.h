#pragma once
// Paints a Drawing with Cairo: the one painter behind the window, PNG, SVG and movie frames.

#include <functional>
#include <string>

#include "pictures/image.h"
#include "render/drawing.h"

typedef struct _cairo cairo_t;

namespace fosssim {

/// Paints `drawing` on `cr`, whose user space must be the drawing's pixels (origin top-left,
/// y down): background, paths, the 3D shapes in their order (triangles filled and outlined,
/// capsules, discs, rings), edges as round-capped strokes, particles as filled circles,
/// marks, guides, then the text lines. Anti-aliased as the target surface allows.
void paint_drawing(cairo_t* cr, const Drawing& drawing);

/// Makes `c` the source colour of `cr` (opaque).
void set_color(cairo_t* cr, const Color& c);

/// `drawing` painted into a new image of its size.
Image render_image(const Drawing& drawing);

/// Writes `drawing` as a PNG file. Written to a temporary file beside it and renamed, so `path` is
/// never half written. Throws Error (kCannotWrite) naming the path and the reason.
void write_png(const Drawing& drawing, const std::string& path);

/// Writes `drawing` as an SVG file (vector shapes, sizes in px), atomically as write_png.
void write_svg(const Drawing& drawing, const std::string& path);

enum class PictureFormat { kPng, kSvg };

/// kSvg when `path` ends in ".svg" (any case), else kPng.
PictureFormat picture_format_for(const std::string& path);

/// Makes a width × height picture, lets `paint` draw on it (user space in pixels, origin top-left)
/// and writes it to `path` as PNG or SVG: to a temporary file first (io/output_file.h), renamed
/// when complete. Throws Error (kCannotWrite) naming the path and Cairo's reason.
void write_picture(const std::string& path, PictureFormat format, int width, int height,
                   const std::function<void(cairo_t*)>& paint);

/// Writes an image as a PNG file, atomically as write_png.
void write_png(const Image& image, const std::string& path);

/// Reads a PNG file into an image (for tests and comparisons); throws Error (kBadInput).
Image read_png(const std::string& path);

}  // namespace fosssim
