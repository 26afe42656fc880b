#pragma once
// Helpers over the settings enums' JSON names, which settings.h declares next to each enum
// (EnumNames<E>::names, index == value). The field table, the JSON reader/writer, the schema and
// the UI all take names through these.
#include "renderer/settings/settings.h"

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace st {

template <class E>
constexpr std::span<const std::string_view> enumNames() {
    return EnumNames<E>::names;
}

// "practical" for SplitScheme::Practical; "<invalid N>" for a value outside the enumerators.
template <class E>
std::string enumName(E value) {
    const auto index = static_cast<std::size_t>(value);
    const auto names = enumNames<E>();
    if (index < names.size()) return std::string(names[index]);
    return "<invalid " + std::to_string(index) + ">";
}

// Index of `name` in `names`, or nullopt. Exact, case-sensitive match.
inline std::optional<int> enumIndex(std::span<const std::string_view> names, std::string_view name) {
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (names[i] == name) return static_cast<int>(i);
    }
    return std::nullopt;
}

// "\"none\", \"distance\", ..." for messages listing the valid names.
inline std::string quotedNames(std::span<const std::string_view> names) {
    std::string text;
    for (const auto name : names) text += (text.empty() ? "\"" : ", \"") + std::string(name) + "\"";
    return text;
}

// parseEnum<FitMode>("sphere") == FitMode::Sphere; nullopt for an unknown name.
template <class E>
std::optional<E> parseEnum(std::string_view name) {
    const auto index = enumIndex(enumNames<E>(), name);
    if (!index) return std::nullopt;
    return static_cast<E>(*index);
}

}  // namespace st
