#pragma once
// JSON names of the settings enums: lowercase-kebab, in enumerator order (index == value).
// The field table, the JSON reader/writer, the schema and the UI all take names from here.
#include "renderer/settings/settings.h"

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace st {

template <class E>
struct EnumNames;  // specialised below; `names[i]` is the JSON name of enumerator value i

template <>
struct EnumNames<SplitScheme> {
    static constexpr std::array<std::string_view, 4> names{"uniform", "logarithmic", "practical", "manual"};
};
template <>
struct EnumNames<FitMode> {
    static constexpr std::array<std::string_view, 3> names{"cascade", "scene", "sphere"};
};
template <>
struct EnumNames<ZExtension> {
    static constexpr std::array<std::string_view, 4> names{"none", "distance", "scene-bounds", "pancake"};
};
template <>
struct EnumNames<Selection> {
    static constexpr std::array<std::string_view, 2> names{"interval", "map"};
};
template <>
struct EnumNames<FilterKind> {
    static constexpr std::array<std::string_view, 3> names{"hard", "pcf2x2", "pcf-nxn"};
};
template <>
struct EnumNames<View> {
    static constexpr std::array<std::string_view, 5> names{"shaded", "cascades", "shadow", "texel-density", "side"};
};

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
