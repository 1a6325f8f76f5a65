#include "outputs/frame_output.h"

#include "pictures/cairo_painter.h"

namespace fosssim {

const Drawing& Frame::drawing() {
  if (!drawing_) drawing_ = view_.compose(state_);
  return *drawing_;
}

const Image& Frame::image() {
  if (!image_) image_ = render_image(drawing());
  return *image_;
}

}  // namespace fosssim
