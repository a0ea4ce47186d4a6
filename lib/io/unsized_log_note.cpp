#include "opf/io/unsized_log_note.h"

namespace opf {

std::string unsized_log_note() {
  return "the occluder module took a hidden object (carried or left) and no detection "
         "states a size (the radius or box_x,box_y,box_z columns): how far each cover reaches is "
         "then unknown, and carried and left are told apart less often (docs/formats.md)";
}

}  // namespace opf
