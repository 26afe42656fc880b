// toJson/fromJson: round trips, defaults for missing fields, and one test per error class. Every
// error message must name the source, the JSON path and the reason.
#include "renderer/settings/settings_json.h"
#include "tests/settings/test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace st {
namespace {

using nlohmann::json;
using test::hasMessage;
using test::preset;
using test::readErrors;

TEST(SettingsJsonTest, DefaultRoundTrips) { EXPECT_EQ(fromJson(toJson(Settings{}), "mem"), Settings{}); }

TEST(SettingsJsonTest, EveryFieldChangedRoundTrips) {
    const Settings s = test::everyFieldChanged();
    EXPECT_EQ(fromJson(toJson(s), "mem"), s);
}

TEST(SettingsJsonTest, AwkwardFloatsRoundTripExactly) {
    Settings s;
    s.cascades.lambda = 1.0f / 3.0f;
    s.camera.fovY = std::nextafter(60.0f, 61.0f);
    s.camera.nearPlane = 1e-4f;
    s.camera.position = {0.1f, -1e5f, 123456.7f};
    EXPECT_EQ(fromJson(toJson(s), "mem"), s);
}

TEST(SettingsJsonTest, WritesVersionFirstAndTidyFloats) {
    const auto written = toOrderedJson(Settings{});
    EXPECT_EQ(written.begin().key(), "version");
    EXPECT_EQ(written["version"], 1);
    EXPECT_EQ(written["bias"]["constant"].dump(), "0.02");  // not 0.019999999552965164
    EXPECT_EQ(written["cascades"]["scheme"], "practical");
    EXPECT_EQ(written["filter"]["kind"], "pcf2x2");
    EXPECT_EQ(written["cascades"]["zExtension"], "scene-bounds");
}

TEST(SettingsJsonTest, MissingFieldsTakeDefaults) {
    Settings expected;
    expected.cascades.count = 2;
    EXPECT_EQ(fromJson(preset({{"cascades", {{"count", 2}}}}), "mem"), expected);
    EXPECT_EQ(fromJson(preset({{"camera", json::object()}}), "mem"), Settings{});
}

TEST(SettingsJsonTest, VersionIsRequired) {
    const auto errors = readErrors(json{{"scene", "builtin:yard"}});
    EXPECT_TRUE(hasMessage(errors, "presets/bad.json: version: missing"));
}

TEST(SettingsJsonTest, OtherVersionsAreRejected) {
    EXPECT_TRUE(hasMessage(readErrors(json{{"version", 2}}), "presets/bad.json: version: unsupported version 2"));
    EXPECT_TRUE(hasMessage(readErrors(json{{"version", "1"}}), "version: expected the integer 1, got string \"1\""));
    EXPECT_TRUE(hasMessage(readErrors(json{{"version", 1.0}}), "version: expected the integer 1, got 1.0"));
}

TEST(SettingsJsonTest, TopLevelMustBeAnObject) {
    EXPECT_TRUE(hasMessage(readErrors(json::array({1, 2})), "presets/bad.json: (top level): expected an object"));
}

TEST(SettingsJsonTest, UnknownTopLevelKey) {
    const auto errors = readErrors(preset({{"cascade", {{"count", 2}}}}));
    EXPECT_TRUE(hasMessage(errors, "presets/bad.json: cascade: unknown key, expected one of: version, scene, notes, ground, origin, "
                                   "camera, light, cascades, filter, bias, output, path, measure"));
}

TEST(SettingsJsonTest, UnknownNestedKey) {
    const auto errors = readErrors(preset({{"camera", {{"near", 0.5}}}}));
    EXPECT_TRUE(hasMessage(
        errors, "presets/bad.json: camera.near: unknown key, expected one of: position, target, fovY, nearPlane, farPlane"));
}

TEST(SettingsJsonTest, DottedKeysAreUnknown) {
    const auto errors = readErrors(preset({{"camera.fovY", 30}}));
    EXPECT_TRUE(hasMessage(errors, "presets/bad.json: camera.fovY: unknown key (nest objects; keys have no dots)"));
}

TEST(SettingsJsonTest, UnknownKeyUnderALeaf) {
    // A leaf given as an object is a type error, not a place to hide unknown keys.
    const auto errors = readErrors(preset({{"cascades", {{"count", {{"value", 2}}}}}}));
    EXPECT_TRUE(hasMessage(errors, "cascades.count: expected an integer, got object"));
}

TEST(SettingsJsonTest, GroupMustBeAnObject) {
    EXPECT_TRUE(hasMessage(readErrors(preset({{"camera", 5}})), "presets/bad.json: camera: expected an object, got 5"));
}

TEST(SettingsJsonTest, FloatGivenAsString) {
    const auto errors = readErrors(preset({{"cascades", {{"lambda", "0.5"}}}}));
    EXPECT_TRUE(hasMessage(errors, "presets/bad.json: cascades.lambda: expected a number, got string \"0.5\""));
}

TEST(SettingsJsonTest, IntGivenAsFloat) {
    EXPECT_TRUE(hasMessage(readErrors(preset({{"cascades", {{"count", 3.5}}}})),
                           "cascades.count: expected an integer, got 3.5"));
    EXPECT_TRUE(hasMessage(readErrors(preset({{"cascades", {{"count", 3.0}}}})),
                           "cascades.count: expected an integer, got 3.0"));
}

TEST(SettingsJsonTest, BoolStringAndEnumTypes) {
    EXPECT_TRUE(hasMessage(readErrors(preset({{"cascades", {{"stabilize", 1}}}})),
                           "cascades.stabilize: expected true or false, got 1"));
    EXPECT_TRUE(hasMessage(readErrors(preset({{"notes", 42}})), "notes: expected a string, got 42"));
    EXPECT_TRUE(hasMessage(readErrors(preset({{"cascades", {{"fit", "tight"}}}})),
                           "presets/bad.json: cascades.fit: must be one of \"cascade\", \"scene\", \"sphere\", \"samples\", \"diagonal\", got "
                           "string \"tight\""));
    EXPECT_TRUE(hasMessage(readErrors(preset({{"filter", {{"kind", 2}}}})), "filter.kind: must be one of"));
}

TEST(SettingsJsonTest, NonFiniteNumbers) {
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(hasMessage(readErrors(preset({{"camera", {{"fovY", inf}}}})),
                           "presets/bad.json: camera.fovY: must be finite, got inf"));
    EXPECT_TRUE(hasMessage(readErrors(preset({{"light", {{"ambient", nan}}}})), "light.ambient: must be finite, got nan"));
    EXPECT_TRUE(hasMessage(readErrors(preset({{"camera", {{"position", {0, -inf, 0}}}}})),
                           "camera.position[1]: must be finite, got -inf"));
}

TEST(SettingsJsonTest, NumberTooBigForAFloat) {
    EXPECT_TRUE(hasMessage(readErrors(preset({{"camera", {{"farPlane", 1e300}}}})),
                           "camera.farPlane: must be in 0.0001..1000000, got 1e+300"));
}

TEST(SettingsJsonTest, OutOfRange) {
    EXPECT_TRUE(hasMessage(readErrors(preset({{"cascades", {{"count", 12}}}})),
                           "presets/bad.json: cascades.count: must be in 1..8, got 12"));
    EXPECT_TRUE(hasMessage(readErrors(preset({{"cascades", {{"count", 0}}}})), "cascades.count: must be in 1..8, got 0"));
    EXPECT_TRUE(hasMessage(readErrors(preset({{"camera", {{"fovY", 180}}}})), "camera.fovY: must be in 1..179, got 180"));
    EXPECT_TRUE(hasMessage(readErrors(preset({{"cascades", {{"blendBand", 0.6}}}})),
                           "cascades.blendBand: must be in 0..0.5, got 0.6"));
    EXPECT_TRUE(hasMessage(readErrors(preset({{"output", {{"width", 8}}}})), "output.width: must be in 16..8192, got 8"));
    EXPECT_TRUE(hasMessage(readErrors(preset({{"cascades", {{"count", 1e20}}}})), "cascades.count: expected an integer"));
    EXPECT_TRUE(hasMessage(readErrors(preset({{"cascades", {{"count", 18446744073709551615u}}}})),
                           "cascades.count: must be in 1..8, got 1844674407370955"));
}

TEST(SettingsJsonTest, MapSizeMustBeAPowerOfTwoInRange) {
    EXPECT_TRUE(hasMessage(readErrors(preset({{"cascades", {{"mapSize", 1000}}}})),
                           "presets/bad.json: cascades.mapSize: must be a power of two in 256..8192, got 1000"));
    EXPECT_TRUE(hasMessage(readErrors(preset({{"cascades", {{"mapSize", 16384}}}})),
                           "cascades.mapSize: must be in 256..8192, got 16384"));
    EXPECT_TRUE(hasMessage(readErrors(preset({{"cascades", {{"mapSize", 128}}}})),
                           "cascades.mapSize: must be in 256..8192, got 128"));
    EXPECT_NO_THROW((void)fromJson(preset({{"cascades", {{"mapSize", 8192}}}}), "mem"));
}

TEST(SettingsJsonTest, FilterSizeMustBeOdd) {
    EXPECT_TRUE(hasMessage(readErrors(preset({{"filter", {{"size", 4}}}})), "filter.size: must be odd, got 4"));
    EXPECT_TRUE(hasMessage(readErrors(preset({{"filter", {{"size", 11}}}})), "filter.size: must be in 3..9, got 11"));
}

TEST(SettingsJsonTest, NearMustBeBeforeFar) {
    const auto errors = readErrors(preset({{"camera", {{"nearPlane", 10}, {"farPlane", 5}}}}));
    EXPECT_TRUE(hasMessage(errors, "presets/bad.json: camera.farPlane: must be greater than camera.nearPlane (10), got 5"));
    EXPECT_EQ(errors.size(), 1u);
    EXPECT_TRUE(hasMessage(readErrors(preset({{"camera", {{"nearPlane", 0}}}})), "camera.nearPlane: must be in 0.0001"));
}

TEST(SettingsJsonTest, CameraTargetMustDifferFromPosition) {
    const auto errors = readErrors(preset({{"camera", {{"position", {1, 2, 3}}, {"target", {1, 2, 3}}}}}));
    EXPECT_TRUE(hasMessage(errors, "camera.target: must differ from camera.position"));
}

TEST(SettingsJsonTest, ShadowDistanceWithinNearAndFar) {
    EXPECT_TRUE(hasMessage(readErrors(preset({{"cascades", {{"shadowDistance", 500}}}})),
                           "presets/bad.json: cascades.shadowDistance: must be 0 (the far plane) or in "
                           "(camera.nearPlane, camera.farPlane] = (0.1, 400], got 500"));
    EXPECT_TRUE(hasMessage(readErrors(preset({{"cascades", {{"shadowDistance", 0.05}}}})),
                           "cascades.shadowDistance: must be 0 (the far plane)"));
    EXPECT_NO_THROW((void)fromJson(preset({{"cascades", {{"shadowDistance", 400}}}}), "mem"));
    EXPECT_NO_THROW((void)fromJson(preset({{"cascades", {{"shadowDistance", 0}}}}), "mem"));
}

TEST(SettingsJsonTest, ManualSplitsNeedCountMinusOneValues) {
    const auto errors = readErrors(preset({{"cascades", {{"scheme", "manual"}, {"manualSplits", {10, 20}}}}}));
    EXPECT_TRUE(hasMessage(errors, "presets/bad.json: cascades.manualSplits: the manual scheme with 4 cascades needs "
                                   "exactly 3 split depths, got 2"));
}

TEST(SettingsJsonTest, ManualSplitsMustIncrease) {
    const auto errors = readErrors(preset({{"cascades", {{"scheme", "manual"}, {"manualSplits", {10, 50, 40}}}}}));
    EXPECT_TRUE(hasMessage(errors, "cascades.manualSplits[2]: must be greater than the previous split (50), got 40"));
    EXPECT_TRUE(hasMessage(readErrors(preset({{"cascades", {{"scheme", "manual"}, {"manualSplits", {10, 10, 40}}}}})),
                           "cascades.manualSplits[1]: must be greater than the previous split (10), got 10"));
}

TEST(SettingsJsonTest, ManualSplitsWithinNearAndEnd) {
    EXPECT_TRUE(hasMessage(readErrors(preset({{"cascades", {{"scheme", "manual"}, {"manualSplits", {0.05, 20, 40}}}}})),
                           "cascades.manualSplits[0]: must be in (camera.nearPlane, camera.farPlane) = (0.1, 400), "
                           "got 0.05"));
    const auto errors = readErrors(preset(
        {{"cascades", {{"scheme", "manual"}, {"shadowDistance", 100}, {"manualSplits", {10, 20, 100}}}}}));
    EXPECT_TRUE(hasMessage(errors, "cascades.manualSplits[2]: must be in (camera.nearPlane, cascades.shadowDistance) "
                                   "= (0.1, 100), got 100"));
}

TEST(SettingsJsonTest, ManualSplitsAreIgnoredByOtherSchemesButMustBeNumbers) {
    const auto ok = fromJson(preset({{"cascades", {{"scheme", "practical"}, {"manualSplits", {300, 20}}}}}), "mem");
    EXPECT_EQ(ok.cascades.manualSplits, (std::vector<float>{300.0f, 20.0f}));
    EXPECT_TRUE(hasMessage(readErrors(preset({{"cascades", {{"manualSplits", {10, "x"}}}}})),
                           "cascades.manualSplits[1]: expected a number, got string \"x\""));
    EXPECT_TRUE(hasMessage(readErrors(preset({{"cascades", {{"manualSplits", 10}}}})),
                           "cascades.manualSplits: expected an array of numbers, got 10"));
}

TEST(SettingsJsonTest, ValidManualSplits) {
    const auto s = fromJson(preset({{"cascades", {{"scheme", "manual"}, {"count", 3}, {"manualSplits", {8, 30}}}}}), "m");
    EXPECT_EQ(s.cascades.scheme, SplitScheme::Manual);
    EXPECT_EQ(s.cascades.manualSplits, (std::vector<float>{8.0f, 30.0f}));
}

TEST(SettingsJsonTest, Vec3Shape) {
    EXPECT_TRUE(hasMessage(readErrors(preset({{"camera", {{"position", {1, 2}}}}})),
                           "presets/bad.json: camera.position: expected an array of 3 numbers, got array [1,2]"));
    EXPECT_TRUE(hasMessage(readErrors(preset({{"camera", {{"target", {1, "2", 3}}}}})),
                           "camera.target[1]: expected a number, got string \"2\""));
    EXPECT_TRUE(hasMessage(readErrors(preset({{"camera", {{"target", {1, 2e6, 3}}}}})),
                           "camera.target[1]: must be in -1000000..1000000, got 2000000"));
}

TEST(SettingsJsonTest, SceneMustNotBeEmpty) {
    EXPECT_TRUE(hasMessage(readErrors(preset({{"scene", ""}})), "presets/bad.json: scene: must not be empty"));
}

TEST(SettingsJsonTest, ReportsEveryErrorNotJustTheFirst) {
    try {
        (void)fromJson(json{{"cascades", {{"count", 12}, {"mapSize", 1000}}}, {"colour", 1}}, "p.json");
        FAIL() << "accepted";
    } catch (const SettingsError& e) {
        const std::vector<std::string> expected = {
            "p.json: version: missing; every preset must say \"version\": 1",
            "p.json: colour: unknown key, expected one of: version, scene, notes, ground, origin, camera, light, cascades, "
            "filter, bias, output, path, measure",
            "p.json: cascades.count: must be in 1..8, got 12",
            "p.json: cascades.mapSize: must be a power of two in 256..8192, got 1000",
        };
        EXPECT_EQ(e.messages(), expected);
        EXPECT_EQ(std::string(e.what()), expected[0] + "\n" + expected[1] + "\n" + expected[2] + "\n" + expected[3]);
    }
}

TEST(SettingsJsonTest, ABrokenFieldIsNotReportedAgainThroughRulesThatReadIt) {
    // nearPlane is unreadable, so "near < far" is not checked against its default.
    const auto errors = readErrors(preset({{"camera", {{"nearPlane", "x"}, {"farPlane", 0.05}}}}));
    ASSERT_EQ(errors.size(), 1u) << errors[0];
    EXPECT_TRUE(hasMessage(errors, "camera.nearPlane: expected a number"));
}

}  // namespace
}  // namespace st
