#include "opf/core/recovery_events.h"

#include <array>
#include <utility>

namespace opf {
namespace {

// The events in the order they are written, each with its word.
constexpr std::array<std::pair<std::string_view, bool RecoveryEvents::*>, 4> kEvents = {{
    {"reset", &RecoveryEvents::sensor_reset},
    {"underflow", &RecoveryEvents::weights_underflow},
    {"capped", &RecoveryEvents::trace_capped},
    {"filled", &RecoveryEvents::frame_filled},
}};

}  // namespace

std::string mode_column(EstimateMode mode, const RecoveryEvents& events) {
  std::string text(to_string(mode));
  for (const auto& [word, flag] : kEvents) {
    if (!(events.*flag)) continue;
    text += '+';
    text += word;
  }
  return text;
}

std::optional<ModeColumn> parse_mode_column(std::string_view text) {
  const std::size_t plus = text.find('+');
  const std::string_view word = text.substr(0, plus);
  ModeColumn column;
  // `occluder`: the word for `carried` before the occluder module kept a `left` hypothesis too,
  // still read so that older estimate files load.
  const std::optional<EstimateMode> mode =
      word == "occluder" ? EstimateMode::kCarried : parse_name(kEstimateModeNames, word);
  if (!mode) return std::nullopt;
  column.mode = *mode;
  // Events follow in the written order, each at most once, so every column has one spelling.
  std::size_t next_event = 0;
  std::string_view rest = plus == std::string_view::npos ? "" : text.substr(plus);
  while (!rest.empty()) {
    rest.remove_prefix(1);  // the '+'
    const std::string_view event = rest.substr(0, rest.find('+'));
    rest.remove_prefix(event.size());
    while (next_event < kEvents.size() && kEvents[next_event].first != event) ++next_event;
    if (next_event == kEvents.size()) return std::nullopt;
    column.events.*(kEvents[next_event].second) = true;
    ++next_event;
  }
  return column;
}

}  // namespace opf
