#include "metrics/ground_truth.h"

#include "metrics/alpha_cutout.h"
#include "metrics/parallel_rows.h"

#include <embree3/rtcore.h>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <chrono>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace st::metrics {
namespace {

// Triangles of alpha-masked materials, with what the filter needs to find the alpha at a hit.
struct MaskedTriangle {
    const Material* material = nullptr;
    glm::vec2 uv[3];
};

struct MaskedData {
    const Scene* scene = nullptr;
    std::vector<MaskedTriangle> triangles;  // by Embree primID
};

const Material& materialOf(const Scene& scene, const DrawItem& item) {
    static const Material kDefault;  // as SceneGpu::draw: an out-of-range index draws the default
    const bool valid = item.material >= 0 && item.material < int(scene.materials.size());
    return valid ? scene.materials[std::size_t(item.material)] : kDefault;
}

// Embree's barycentrics: hit = (1-u-v) v0 + u v1 + v v2; rejects hits on cut-out texels.
void occludedFilter(const RTCFilterFunctionNArguments* args) {
    const auto* data = static_cast<const MaskedData*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const MaskedTriangle& t = data->triangles[RTCHitN_primID(args->hit, args->N, i)];
        const float u = RTCHitN_u(args->hit, args->N, i);
        const float v = RTCHitN_v(args->hit, args->N, i);
        const glm::vec2 uv = (1.0f - u - v) * t.uv[0] + u * t.uv[1] + v * t.uv[2];
        if (cutOut(*data->scene, *t.material, uv)) args->valid[i] = 0;
    }
}

}  // namespace

struct GroundTruth::Impl {
    const Scene* scene = nullptr;
    RTCDevice device = nullptr;
    RTCScene bvh = nullptr;
    MaskedData masked;
    double buildMs = 0.0;

    ~Impl() {
        if (bvh) rtcReleaseScene(bvh);
        if (device) rtcReleaseDevice(device);
    }

    // The scene's vertex positions, shared by both geometries (Embree reads 16 bytes per vertex,
    // hence the padding float).
    RTCBuffer positions() const {
        RTCBuffer buffer = rtcNewBuffer(device, (scene->vertices.size() * 3 + 1) * sizeof(float));
        auto* out = static_cast<float*>(rtcGetBufferData(buffer));
        for (std::size_t i = 0; i < scene->vertices.size(); ++i)
            std::memcpy(out + 3 * i, &scene->vertices[i].position.x, 3 * sizeof(float));
        out[scene->vertices.size() * 3] = 0.0f;
        return buffer;
    }

    void addGeometry(RTCBuffer vertices, const std::vector<std::uint32_t>& indices, bool alphaMasked) {
        if (indices.empty()) return;
        RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, vertices, 0, 3 * sizeof(float),
                             scene->vertices.size());
        void* out = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                            3 * sizeof(std::uint32_t), indices.size() / 3);
        std::memcpy(out, indices.data(), indices.size() * sizeof(std::uint32_t));
        if (alphaMasked) {
            rtcSetGeometryUserData(geom, &masked);
            rtcSetGeometryOccludedFilterFunction(geom, occludedFilter);
            rtcSetGeometryIntersectFilterFunction(geom, occludedFilter);  // the blocker distance's ray
        }
        rtcCommitGeometry(geom);
        rtcAttachGeometry(bvh, geom);
        rtcReleaseGeometry(geom);
    }

    void build() {
        std::vector<std::uint32_t> opaque, cut;
        masked.scene = scene;
        for (const DrawItem& item : scene->draws) {
            const Material& m = materialOf(*scene, item);
            auto& list = m.alphaMask ? cut : opaque;
            for (std::uint32_t k = 0; k + 2 < item.indexCount; k += 3) {
                const std::uint32_t* tri = &scene->indices[item.firstIndex + k];
                list.insert(list.end(), tri, tri + 3);
                if (m.alphaMask)
                    masked.triangles.push_back({&m, {scene->vertices[tri[0]].uv, scene->vertices[tri[1]].uv,
                                                     scene->vertices[tri[2]].uv}});
            }
        }
        RTCBuffer vertices = positions();
        addGeometry(vertices, opaque, false);
        addGeometry(vertices, cut, true);
        rtcReleaseBuffer(vertices);
        rtcCommitScene(bvh);
    }

    bool occluded(glm::vec3 origin, glm::vec3 dir) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRay ray{};
        ray.org_x = origin.x;
        ray.org_y = origin.y;
        ray.org_z = origin.z;
        ray.dir_x = dir.x;
        ray.dir_y = dir.y;
        ray.dir_z = dir.z;
        ray.tnear = 0.0f;
        ray.tfar = std::numeric_limits<float>::infinity();
        ray.mask = 0xFFFFFFFFu;
        rtcOccluded1(bvh, &context, &ray);
        return ray.tfar < 0.0f;  // Embree sets tfar to -inf when something blocks the ray
    }
};

namespace {

// The first hit along one ray, +inf if none.
float hitDistance(RTCScene bvh, glm::vec3 origin, glm::vec3 dir) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh{};
    rh.ray.org_x = origin.x;
    rh.ray.org_y = origin.y;
    rh.ray.org_z = origin.z;
    rh.ray.dir_x = dir.x;
    rh.ray.dir_y = dir.y;
    rh.ray.dir_z = dir.z;
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = std::numeric_limits<float>::infinity();
    rh.ray.mask = 0xFFFFFFFFu;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(bvh, &context, &rh);
    return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? std::numeric_limits<float>::infinity() : rh.ray.tfar;
}

// How many of `count` directions from `origin` reach the sun, traced 8 at a time: the rays of a
// pixel share their origin and differ by a fraction of a degree, the coherent case packets are
// for.
int raysReachingSun(RTCScene bvh, glm::vec3 origin, const glm::vec3* dirs, int count) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    int reached = 0;
    for (int first = 0; first < count; first += 8) {
        alignas(32) int valid[8];
        RTCRay8 rays;
        const int n = std::min(8, count - first);
        for (int j = 0; j < 8; ++j) {
            const glm::vec3 d = dirs[first + std::min(j, n - 1)];
            valid[j] = j < n ? -1 : 0;
            rays.org_x[j] = origin.x;
            rays.org_y[j] = origin.y;
            rays.org_z[j] = origin.z;
            rays.dir_x[j] = d.x;
            rays.dir_y[j] = d.y;
            rays.dir_z[j] = d.z;
            rays.tnear[j] = 0.0f;
            rays.tfar[j] = std::numeric_limits<float>::infinity();
            rays.time[j] = 0.0f;
            rays.mask[j] = 0xFFFFFFFFu;
            rays.id[j] = unsigned(j);
            rays.flags[j] = 0;
        }
        rtcOccluded8(valid, bvh, &context, &rays);
        for (int j = 0; j < n; ++j) reached += rays.tfar[j] >= 0.0f;  // -inf where something blocks
    }
    return reached;
}

}  // namespace

GroundTruth::GroundTruth(const Scene& scene) : impl_(std::make_unique<Impl>()) {
    const auto t0 = std::chrono::steady_clock::now();
    impl_->scene = &scene;
    impl_->device = rtcNewDevice(nullptr);
    if (!impl_->device) throw std::runtime_error("ground truth: Embree could not create a device");
    impl_->bvh = rtcNewScene(impl_->device);
    rtcSetSceneBuildQuality(impl_->bvh, RTC_BUILD_QUALITY_HIGH);  // built once, traced many times
    impl_->build();
    if (rtcGetDeviceError(impl_->device) != RTC_ERROR_NONE)
        throw std::runtime_error("ground truth: Embree failed to build the BVH of " + scene.name);
    impl_->buildMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

GroundTruth::~GroundTruth() = default;

double GroundTruth::buildMs() const { return impl_->buildMs; }

bool GroundTruth::reachesSun(glm::vec3 wsOrigin, glm::vec3 wsToSun) const {
    return !impl_->occluded(wsOrigin, glm::normalize(wsToSun));
}

bool GroundTruth::lit(glm::vec3 wsPoint, glm::vec3 wsNormal, glm::vec3 wsToSun, glm::vec3 wsEye,
                      RayOffset offset) const {
    const float eps =
        offset.metres + offset.perMetre * std::max(glm::length(wsPoint), glm::length(wsPoint - wsEye));
    return !impl_->occluded(wsPoint + wsNormal * eps, glm::normalize(wsToSun));
}

std::vector<std::uint8_t> GroundTruth::trace(const MeasureSamples& samples, glm::vec3 wsToSun, glm::vec3 wsEye,
                                             RayOffset offset, const RowControl& control) const {
    std::vector<std::uint8_t> out(samples.size(), 0);
    forEachRowParallel(samples.height, [&](int y) {
        for (std::size_t i = std::size_t(y) * samples.width, end = i + samples.width; i < end; ++i) {
            if (!samples.receiver(i)) continue;
            out[i] = lit(glm::vec3(samples.position[i]), glm::vec3(samples.geometry[i]), wsToSun, wsEye, offset);
        }
    }, control);
    return out;
}

SoftTruth GroundTruth::traceDisc(const MeasureSamples& samples, glm::vec3 wsToSun, const SunDisc& disc,
                                 glm::vec3 wsEye, RayOffset offset, const RowControl& control) const {
    SoftTruth out;
    out.visible.assign(samples.size(), 0.0f);
    out.blocker.assign(samples.size(), std::numeric_limits<float>::infinity());
    const DiscFrame frame = discFrame(wsToSun, disc.angularDiameter);
    const bool point = disc.angularDiameter <= 0.0f || disc.rays <= 0;
    const int rays = point ? 0 : disc.rays;
    const int first = std::min(rays, kDiscFirstRays);
    const int w = samples.width;
    auto origin = [&](std::size_t i) {
        const glm::vec3 p(samples.position[i]);
        const float eps = offset.metres + offset.perMetre * std::max(glm::length(p), glm::length(p - wsEye));
        return p + glm::vec3(samples.geometry[i]) * eps;
    };
    // Rays k0..k1-1 of pixel i's pattern that reach the sun.
    auto reaching = [&](std::size_t i, int k0, int k1, std::vector<glm::vec3>& dirs) {
        const DiscScramble scramble = discScramble(disc.seed, i);
        dirs.resize(std::size_t(k1 - k0));
        for (int k = k0; k < k1; ++k)
            dirs[std::size_t(k - k0)] = frame.direction(concentricDisc(squareSample(std::uint32_t(k), scramble)));
        return raysReachingSun(impl_->bvh, origin(i), dirs.data(), k1 - k0);
    };

    // Pass 1: the centre ray (blocker distance) and the first rays of every receiver.
    std::vector<std::uint8_t> firstReached(samples.size(), 0);
    forEachRowParallel(samples.height, [&](int y) {
        std::vector<glm::vec3> dirs;
        for (std::size_t i = std::size_t(y) * w, end = i + w; i < end; ++i) {
            if (!samples.receiver(i)) continue;
            out.blocker[i] = hitDistance(impl_->bvh, origin(i), frame.toSun);
            if (point) out.visible[i] = std::isinf(out.blocker[i]) ? 1.0f : 0.0f;
            else firstReached[i] = std::uint8_t(reaching(i, 0, first, dirs));
        }
    }, control);
    if (point || control.cancelled()) return out;

    // Pass 2: the rest of the rays where the pixel or a receiver of its 3x3 block is not
    // unanimous (centre and first rays all lit, or all blocked, and the same for the block).
    // Elsewhere the pixel is fully lit or in umbra: a penumbra is a band of pixels, and the
    // 9 x (1 + kDiscFirstRays) rays of a block see any caster covering an eighth of the disc.
    auto state = [&](std::size_t i) {  // 0 all blocked, 2 all lit, 1 mixed
        const bool centreLit = std::isinf(out.blocker[i]);
        if (firstReached[i] == 0 && !centreLit) return 0;
        if (firstReached[i] == first && centreLit) return 2;
        return 1;
    };
    forEachRowParallel(samples.height, [&](int y) {
        std::vector<glm::vec3> dirs;
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            if (!samples.receiver(i)) continue;
            const int own = state(i);
            bool unanimous = !disc.exhaustive && own != 1;
            for (int ny = std::max(y - 1, 0); unanimous && ny <= std::min(y + 1, samples.height - 1); ++ny)
                for (int nx = std::max(x - 1, 0); unanimous && nx <= std::min(x + 1, w - 1); ++nx) {
                    const std::size_t n = std::size_t(ny) * std::size_t(w) + std::size_t(nx);
                    unanimous = !samples.receiver(n) || state(n) == own;
                }
            const int reached = unanimous ? (own == 2 ? rays : 0) : firstReached[i] + reaching(i, first, rays, dirs);
            out.visible[i] = float(reached) / float(rays);
        }
    }, control);
    return out;
}

}  // namespace st::metrics
