#pragma once
// Shared helpers of the settings tests: a Settings with every field changed, error capture and
// a scratch directory.
#include "renderer/settings/settings.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace st::test {

// Valid, and every field differs from Settings{} (checked by FieldTableTest).
Settings everyFieldChanged();

// {"version": 1} with `patch` merged in (RFC 7386: null removes a key).
nlohmann::json preset(const nlohmann::json& patch);

inline constexpr const char* kSource = "presets/bad.json";

// The messages fromJson(json, kSource) throws; an empty list (and a test failure) if it accepts.
std::vector<std::string> readErrors(const nlohmann::json& json);

// Passes if one of `messages` contains `part`; otherwise lists them all.
::testing::AssertionResult hasMessage(const std::vector<std::string>& messages, std::string_view part);

// A fresh, empty directory for the current test, removed by TearDown.
class ScratchDir : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;
    std::vector<std::string> entries() const;  // file names in dir, sorted
    std::filesystem::path dir;
};

}  // namespace st::test
