#include "opf/core/estimator.h"

#include <sstream>
#include <stdexcept>

namespace opf {

double time_step(std::string_view estimator, double previous, double t) {
  const double dt = t - previous;
  if (!(dt > 0.0)) {
    std::ostringstream msg;
    msg << estimator << ": time " << t << " s does not follow the previous time " << previous
        << " s";
    throw std::invalid_argument(msg.str());
  }
  return dt;
}

}  // namespace opf
