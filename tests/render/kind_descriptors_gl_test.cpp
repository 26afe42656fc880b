// The kinds' descriptors against the renderer (issue 19): a field the descriptors say does not
// apply leaves the image bit for bit as it was, and a per-cascade bias factor changes the pixels
// of its own cascade only. Small images and maps so the test stays fast on llvmpipe.
#include "renderer/scene/scene.h"
#include "renderer/settings/enum_names.h"
#include "renderer/settings/kind_descriptors.h"
#include "renderer/settings/validation.h"
#include "tests/render/render_test_util.h"
#include "tests/support/gl_fixture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

using namespace st;

namespace {
class KindDescriptorsGLTest : public test::GLTest {};

// A low sun over the box-over-plane scene, two cascades of 256 texels, 128x72 pixels.
Settings smallScene() {
    Settings s = test::boxOverPlaneView({0.0f, 9.0f, 16.0f}, {0.0f, 0.0f, 0.0f}, 60.0f);
    s.light.elevation = 25.0f;
    s.cascades.count = 2;
    s.cascades.mapSize = 256;
    s.output = {.width = 128, .height = 72, .view = View::Shaded};
    return s;
}

// Another legal value of a scalar field (Float, Int, Bool, Enum), or of a list (count factors);
// nullopt for kinds no mode gates (strings, vectors, keyframes).
std::optional<FieldValue> perturbed(const FieldInfo& f, const Settings& s) {
    const FieldValue v = f.get(s);
    switch (f.kind) {
        case FieldKind::Bool: return FieldValue(!std::get<bool>(v));
        case FieldKind::Enum:
            return FieldValue(std::in_place_type<int>, (std::get<int>(v) + 1) % int(f.enumNames.size()));
        case FieldKind::Float: {
            const double x = std::get<float>(v), up = x + 0.25 * (f.max - f.min);
            return FieldValue(float(up <= f.max ? up : (f.min + x) / 2.0));
        }
        case FieldKind::Int: {
            const int x = std::get<int>(v);
            const int step = f.powerOfTwo ? x : f.odd ? 2 : 1;
            return FieldValue(std::in_place_type<int>, x + step <= f.max ? x + step : (f.powerOfTwo ? x / 2 : x - step));
        }
        case FieldKind::FloatList:
            return FieldValue(std::vector<float>(std::size_t(s.cascades.count), float(f.min + 0.4 * (f.max - f.min) / 2.0)));
        case FieldKind::IntList:
            return FieldValue(std::vector<int>(std::size_t(s.cascades.count), 512));
        default: return std::nullopt;
    }
}

struct Base {
    const char* name;
    Settings s;
};

std::vector<Base> bases() {
    Settings pcf = smallScene();
    pcf.bias.normalOffset = 0.0f;  // its factors then do nothing
    Settings vsm = smallScene();
    vsm.filter.kind = FilterKind::Vsm;
    Settings pcss = smallScene();
    pcss.filter.kind = FilterKind::Pcss;
    pcss.cascades.storage = CascadeStorage::Atlas;
    pcss.cascades.zExtension = ZExtension::Pancake;
    Settings evsm4 = smallScene();
    evsm4.filter.kind = FilterKind::Evsm4;
    evsm4.cascades.scheme = SplitScheme::Logarithmic;
    Settings one = smallScene();  // one cascade: no split to place, nothing to blend into
    one.cascades.count = 1;
    one.filter.kind = FilterKind::PcfNxN;
    return {{"pcf2x2/array", pcf}, {"vsm", vsm}, {"pcss/atlas", pcss}, {"evsm4/logarithmic", evsm4},
            {"pcf-nxn/one cascade", one}};
}

int differingBytes(const Rgba8Image& a, const Rgba8Image& b) {
    int n = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) n += a.pixels[i] != b.pixels[i];
    return n;
}

}  // namespace

// Every field of the table that does not apply to a base (a filter parameter of another kind, the
// atlas padding of an array, lambda of a logarithmic scheme, a factor of a zero bias, ...), set to
// another legal value, leaves the image identical. A gated field that does apply changes it, so
// the comparison can fail.
TEST_F(KindDescriptorsGLTest, AFieldAKindDoesNotReadLeavesItsImageUnchanged) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    int compared = 0;
    for (const Base& base : bases()) {
        ASSERT_TRUE(validate(base.s).empty()) << base.name;
        const Rgba8Image reference = test::renderImage(r, base.s);
        for (const FieldInfo& f : fieldTable()) {
            if (fieldApplies(base.s, f.path) || f.change == ChangeClass::None) continue;
            const std::optional<FieldValue> value = perturbed(f, base.s);
            if (!value) continue;
            Settings changed = base.s;
            f.set(changed, *value);
            if (!validate(changed).empty() || changed == base.s) continue;  // e.g. map sizes of an array
            EXPECT_EQ(differingBytes(reference, test::renderImage(r, changed)), 0) << base.name << ": " << f.path;
            ++compared;
        }
    }
    EXPECT_GE(compared, 40);
    // The control: fields the pcf2x2 base does read change its image.
    const Settings pcf = bases()[0].s;
    const Rgba8Image reference = test::renderImage(r, pcf);
    for (const char* path : {"bias.receiverPlane", "bias.constant", "filter.kind"}) {
        ASSERT_TRUE(fieldApplies(pcf, path)) << path;
        Settings changed = pcf;
        findField(path)->set(changed, *perturbed(*findField(path), pcf));
        EXPECT_GT(differingBytes(reference, test::renderImage(r, changed)), 0) << path;
    }
}

// Cascade 1's constant bias raised (factor 40 on a 0.001 m bias): cascade 0's pixels stay bit for
// bit, and cascade 1's change exactly as when the global bias is raised by 40 (which changes both
// cascades, so the comparison can fail). Which cascade a pixel is in comes from the cascades view
// (cascade 0 is tinted red, 1 green: renderer/render/cascade_tints.h).
TEST_F(KindDescriptorsGLTest, ABiasFactorChangesOnlyItsCascadesPixels) {
    Scene scene = makeBuiltinScene("box-over-plane");
    Renderer r(scene);
    Settings s = smallScene();
    s.light.elevation = 20.0f;
    s.bias = {.constant = 0.001f, .slope = 0.0f, .normalOffset = 0.0f, .receiverPlane = false};
    s.output.view = View::Cascades;
    const Rgba8Image tints = test::renderImage(r, s);
    s.output.view = View::Shadow;
    const Rgba8Image before = test::renderImage(r, s);
    Settings global = s;
    global.bias.constant *= 40.0f;
    const Rgba8Image raisedAll = test::renderImage(r, global);
    s.bias.constantScale = {1.0f, 40.0f};
    ASSERT_TRUE(validate(s).empty());
    const Rgba8Image raisedOne = test::renderImage(r, s);
    int pixels[2] = {0, 0}, changedOne[2] = {0, 0}, changedAll[2] = {0, 0}, differ = 0;
    for (std::size_t i = 0; i < tints.pixels.size(); i += 4) {
        const int red = tints.pixels[i], green = tints.pixels[i + 1];
        const int c = red > green + 20 ? 0 : green > red + 20 ? 1 : -1;
        if (c < 0) continue;
        ++pixels[c];
        changedOne[c] += before.pixels[i] != raisedOne.pixels[i];
        changedAll[c] += before.pixels[i] != raisedAll.pixels[i];
        differ += c == 1 && raisedOne.pixels[i] != raisedAll.pixels[i];
    }
    ASSERT_GT(pixels[0], 500);
    ASSERT_GT(pixels[1], 500);
    EXPECT_GT(changedAll[0], 20) << "the control: a raised global bias changes cascade 0";
    EXPECT_GT(changedAll[1], 20);
    EXPECT_EQ(changedOne[0], 0) << "of " << pixels[0] << " pixels of cascade 0";
    EXPECT_EQ(changedOne[1], changedAll[1]) << "of " << pixels[1] << " pixels of cascade 1";
    EXPECT_EQ(differ, 0);
    // Factors of 1 are today's image, bit for bit.
    s.bias.constantScale = {1.0f, 1.0f};
    s.bias.slopeScale = {1.0f, 1.0f};
    EXPECT_EQ(differingBytes(before, test::renderImage(r, s)), 0);
}
