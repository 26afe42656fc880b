#include "sweep/sweep_run.h"

#include "renderer/image/image_io.h"
#include "renderer/settings/settings_json.h"

#include <chrono>
#include <fstream>
#include <set>
#include <stdexcept>

namespace st::sweep {
namespace fs = std::filesystem;
namespace {
using Clock = std::chrono::steady_clock;

// Ordered: a point's figures keep the order they were written in (the CSV's columns).
nlohmann::ordered_json readJson(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error(file.string() + ": cannot read");
    try {
        return nlohmann::ordered_json::parse(in);
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(file.string() + ": not valid JSON: " + e.what());
    }
}

void makeDir(const fs::path& dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir)) throw std::runtime_error(dir.string() + ": cannot create output folder: " +
                                                               (ec ? ec.message() : "not a directory"));
}

// The folder's manifest must be this sweep's (or absent: a new folder).
void claimFolder(const fs::path& dir, const Manifest& m) {
    makeDir(dir / "points");
    const fs::path file = dir / "sweep.json";
    if (fs::exists(file)) {
        const Manifest there = manifestFromJson(readJson(file), file.string());
        if (there.fingerprint != m.fingerprint)
            throw std::runtime_error(dir.string() + ": holds results of another sweep (\"" + there.sweep + "\", " +
                                     std::to_string(there.pointIds.size()) + " points, fingerprint " + there.fingerprint +
                                     "); give another --out or remove it");
        // Modelled costs of two profiles do not compare: the front would mix them.
        if (!there.costProfile.empty() && there.costProfile != m.costProfile)
            throw std::runtime_error(dir.string() + ": its points were modelled with the cost profile \"" +
                                     there.costProfile + "\", this run uses \"" +
                                     (m.costProfile.empty() ? std::string("none") : m.costProfile) +
                                     "\"; give another --out, or the same --profile");
    }
    writeTextAtomic(file, toJson(m).dump(2) + "\n");
}

bool alreadyMeasured(const fs::path& file, const Point& p) {
    if (!fs::exists(file)) return false;
    try {
        return pointFromJson(readJson(file), file.string()).id == p.id;
    } catch (const std::runtime_error&) {
        return false;  // unreadable: measure it again (it is rewritten atomically)
    }
}

PointResult measurePoint(metrics::MeasureSession& session, const SweepSpec& spec, const Point& p, const RunOptions& opt) {
    metrics::MeasureOptions mo;
    mo.costFrames = opt.costFrames;
    mo.costProfile = opt.costProfile;
    const metrics::PresetMeasurement m = session.measure(p.settings, spec.presetDir, mo);
    return {p.id, p.label, p.reference, p.axisValues, toOrderedJson(p.settings), figuresOf(m)};
}
}  // namespace

std::vector<PointResult> readPoints(const fs::path& dir, const Manifest& m) {
    std::vector<PointResult> results;
    for (const std::string& id : m.pointIds) {
        const fs::path file = dir / "points" / (id + ".json");
        if (fs::exists(file)) results.push_back(pointFromJson(readJson(file), file.string()));
    }
    return results;
}

RunOutcome runSweep(const SweepSpec& spec, const RunOptions& opt) {
    const std::vector<Point> all = expandPoints(spec);
    const std::vector<Point> mine = shardOf(all, opt.shardIndex, opt.shardCount);
    const Manifest manifest = manifestOf(spec, all, opt.machine, opt.costProfile ? metrics::profileName(*opt.costProfile) : "");
    claimFolder(opt.outDir, manifest);
    metrics::MeasureSession session;
    RunOutcome out{0, 0, mine.size(), false, {}};
    const auto start = Clock::now();
    for (const Point& p : mine) {
        const fs::path file = opt.outDir / "points" / (p.id + ".json");
        if (alreadyMeasured(file, p)) {
            ++out.resumed;
        } else {
            if ((opt.stopRequested && opt.stopRequested()) || (opt.stopAfter >= 0 && long(out.measured) >= opt.stopAfter)) {
                out.stopped = true;
                break;
            }
            writeTextAtomic(file, toJson(measurePoint(session, spec, p, opt)).dump(2) + "\n");
            ++out.measured;
        }
        if (opt.progress) {
            Progress pr{out.measured + out.resumed, mine.size(), out.resumed, 0.0, -1.0, p.label};
            pr.elapsedS = std::chrono::duration<double>(Clock::now() - start).count();
            if (out.measured > 0) pr.etaS = pr.elapsedS / double(out.measured) * double(mine.size() - pr.done);
            opt.progress(pr);
        }
    }
    out.front = writeReport(opt.outDir, manifest, readPoints(opt.outDir, manifest), opt.report);
    return out;
}

std::size_t mergeSweeps(const std::vector<fs::path>& dirs, const fs::path& outDir, const ReportOptions& report) {
    if (dirs.empty()) throw std::runtime_error("--merge needs at least one sweep folder");
    std::optional<Manifest> first;
    std::set<std::string> machines;
    std::vector<std::pair<fs::path, Manifest>> inputs;
    for (const fs::path& dir : dirs) {
        const fs::path file = dir / "sweep.json";
        if (!fs::exists(file)) throw std::runtime_error(dir.string() + ": not a sweep folder (no sweep.json)");
        Manifest m = manifestFromJson(readJson(file), file.string());
        if (first && m.fingerprint != first->fingerprint)
            throw std::runtime_error(dir.string() + ": holds another sweep (\"" + m.sweep + "\") than " + dirs.front().string());
        if (!first) first = m;
        machines.insert(m.machine);
        inputs.push_back({dir, std::move(m)});
    }
    Manifest merged = *first;
    merged.machine.clear();
    for (const std::string& machine : machines) merged.machine += (merged.machine.empty() ? "" : " + ") + machine;
    claimFolder(outDir, merged);
    for (const auto& [dir, m] : inputs)
        for (const PointResult& r : readPoints(dir, m))
            writeTextAtomic(outDir / "points" / (r.id + ".json"), toJson(r).dump(2) + "\n");
    const std::vector<PointResult> results = readPoints(outDir, merged);
    writeReport(outDir, merged, results, report);
    return results.size();
}

}  // namespace st::sweep
