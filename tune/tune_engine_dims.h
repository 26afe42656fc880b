#pragma once
// What the engines' tuning spaces share (tune_engine*.cpp): candidates in the engine's units, and
// each engine's dimensions. A new engine's space is a function here, defined in its own file, and
// one line in tune_engine.cpp's engineSpace.
#include "renderer/settings/settings.h"
#include "tune/tune_space.h"

#include <nlohmann/json.hpp>

#include <initializer_list>
#include <vector>

namespace st::tune {

std::vector<nlohmann::json> engineNumbers(std::initializer_list<double> values);
std::vector<nlohmann::json> engineNames(std::initializer_list<const char*> values);
// The shadow distance (0 = the camera's far plane) and the split depths as shares of the far plane.
std::vector<nlohmann::json> engineDistances(const Settings& base);
std::vector<nlohmann::json> engineSplitDepths(const Settings& base);

void unityDims(Space& s, const Settings& base);     // tune_engine_unity_unreal.cpp
void unrealDims(Space& s, const Settings& base);    // tune_engine_unity_unreal.cpp
void bevyDims(Space& s, const Settings& base);      // tune_engine_bevy_filament.cpp
void filamentDims(Space& s, const Settings& base);  // tune_engine_bevy_filament.cpp

}  // namespace st::tune
