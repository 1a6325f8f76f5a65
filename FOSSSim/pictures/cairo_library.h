#pragma once
// Cairo, loaded when the first picture is drawn rather than when a program starts.
//
// Linking Cairo made every FOSSSim run load it and the 17 libraries it needs (pixman,
// fontconfig, freetype, PNG, the X11/xcb client libraries, ...), headless runs that draw
// nothing included: the dynamic loader's work for a run of the contest timing scene
// (docs/limits-and-failures.md, "Start-up"). The pictures code calls Cairo through this table
// instead, filled from libcairo.so.2 with dlopen on first use.

#include <cairo-svg.h>
#include <cairo.h>

#include "core/shared_library.h"

namespace fosssim {

// The Cairo functions the pictures code calls, without their "cairo_" prefix.
#define FOSSSIM_CAIRO_FUNCTIONS(X)                                                             \
  X(arc) X(clip) X(clip_extents) X(close_path) X(create) X(destroy) X(fill) X(font_extents)    \
  X(format_stride_for_width) X(image_surface_create) X(image_surface_create_for_data)          \
  X(image_surface_create_from_png) X(image_surface_get_data) X(image_surface_get_height)       \
  X(image_surface_get_stride) X(image_surface_get_width) X(line_to) X(move_to) X(new_path)     \
  X(new_sub_path) X(paint) X(rectangle) X(restore) X(rotate) X(save) X(select_font_face)       \
  X(set_dash) X(set_font_size) X(set_line_cap) X(set_line_join) X(set_line_width)              \
  X(set_operator) X(set_source_rgb) X(set_source_surface) X(show_text) X(status_to_string)     \
  X(stroke) X(surface_destroy) X(surface_finish) X(surface_flush) X(surface_status)            \
  X(surface_write_to_png_stream) X(svg_surface_create_for_stream)                              \
  X(svg_surface_set_document_unit) X(text_extents) X(translate)

/// Cairo's functions: `cairo().move_to(cr, x, y)` calls cairo_move_to(cr, x, y).
struct CairoLibrary {
  // Debian's libcairo2, by the soname cairo.h was built against.
  SharedLibrary library =
      SharedLibrary::open({"libcairo.so.2"}, "pictures need Cairo", "libcairo2");
#define FOSSSIM_CAIRO_MEMBER(name) \
  decltype(&::cairo_##name) name = library.symbol<decltype(&::cairo_##name)>("cairo_" #name);
  FOSSSIM_CAIRO_FUNCTIONS(FOSSSIM_CAIRO_MEMBER)
#undef FOSSSIM_CAIRO_MEMBER
};

/// Cairo, loaded on the first call (thread-safe) and kept for the life of the process. Throws
/// Error (kUnavailable) naming the library and the loader's reason when it cannot be loaded
/// or lacks one of the functions (core/shared_library.h).
const CairoLibrary& cairo();

}  // namespace fosssim
