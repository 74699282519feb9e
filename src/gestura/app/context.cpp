#include "gestura/app/context.hpp"

#include "gestura/core/error.hpp"

namespace gestura::app {

void RunContext::check_stop() const {
  if (stop.stop_requested()) throw Cancelled("stopped on request");
}

}  // namespace gestura::app
