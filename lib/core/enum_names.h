#pragma once
// One table per enum of the words that settings files, result files and the command line spell
// it with, and the three things done with such a table: a value's word, a word's value, and the
// "a, b or c" list an error message offers. Each table sits beside its enum; readers, writers
// and messages all go through it, so a word is never spelled in two places.

#include <array>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace opf {

template <class Enum>
struct EnumName {
  Enum value;
  std::string_view name;
};

template <class Enum, std::size_t N>
using EnumNames = std::array<EnumName<Enum>, N>;

/// The word of `value`; std::invalid_argument when the table lacks it (a table out of step with
/// its enum).
template <class Enum, std::size_t N>
constexpr std::string_view name_of(const EnumNames<Enum, N>& table, Enum value) {
  for (const auto& entry : table)
    if (entry.value == value) return entry.name;
  throw std::invalid_argument("no name for enum value " + std::to_string(static_cast<int>(value)));
}

/// The value spelled `name`, or nothing.
template <class Enum, std::size_t N>
constexpr std::optional<Enum> parse_name(const EnumNames<Enum, N>& table, std::string_view name) {
  for (const auto& entry : table)
    if (entry.name == name) return entry.value;
  return std::nullopt;
}

/// The words in table order as an error message lists them: "a", "a or b", "a, b or c".
template <class Enum, std::size_t N>
std::string name_list(const EnumNames<Enum, N>& table) {
  std::string text;
  for (std::size_t i = 0; i < N; ++i) {
    if (i > 0) text += i + 1 == N ? " or " : ", ";
    text += table[i].name;
  }
  return text;
}

}  // namespace opf
