#pragma once
// Which fields each kind reads, said once (issue 19): a descriptor per value of every mode field
// (filter.kind, cascades.storage, cascades.selection, cascades.scheme, ...) listing the fields of
// the table that value reads, plus the few rules that hang on a number (blend band needs two
// cascades, a per-cascade bias scale does nothing while its bias is 0). The editor's greying,
// validation, the engine exporters and the tuner all ask here instead of keeping if-chains.
// Pure: no GL, no JSON.
#include "renderer/settings/field_table.h"
#include "renderer/settings/settings.h"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace st {

// What one value of a mode field reads among the fields that field gates.
struct KindDescriptor {
    int value = 0;                            // the enumerator (its shader code)
    std::string_view name;                    // its JSON name: "pcf-nxn"
    std::vector<std::string_view> reads;      // gated fields this value reads (field table paths)
    // filter.kind only: the storages it can sample (others are a validation error). Empty = any.
    std::vector<CascadeStorage> storages;
};

// A mode field and its descriptors, one per enumerator, by value.
struct ModeDescriptor {
    std::string_view field;                   // "filter.kind"
    std::vector<std::string_view> gates;      // the union of its kinds' reads: the fields it gates
    std::vector<KindDescriptor> kinds;
};

// Every mode field that gates others: filter.kind, filter.screenSpace, cascades.scheme,
// cascades.zExtension, cascades.storage, cascades.selection, output.view.
const std::vector<ModeDescriptor>& modeDescriptors();

// The descriptor of one mode field ("filter.kind"), or nullptr.
const ModeDescriptor* findMode(std::string_view modeField);

// The descriptor of a filter kind / storage / selection (shortcuts over modeDescriptors()).
const KindDescriptor& describe(FilterKind kind);
const KindDescriptor& describe(CascadeStorage storage);
const KindDescriptor& describe(Selection selection);

// Fields no mode gates: they change the shadow (or the scene, the view, the measurement) whatever
// the kinds are. Together with the modes' gates this covers the whole field table (tested).
std::span<const std::string_view> kindIndependentFields();

// True when `path` (a field table path) changes the result of `s`: its rendered image or its
// measured figures. False for a field the current kinds do not read (filter.evsmNegative with
// filter.kind "pcf2x2"), a per-cascade bias scale whose bias is 0, a blend band or a split scheme
// (and its lambda, manual splits) with one cascade, and notes. Unknown paths are false. An element path ("bias.constantScale[1]") is its field's.
// Use it where the tuner's applies(s, path) was: fieldApplies(s, path).
bool fieldApplies(const Settings& s, std::string_view path);

// Why `path` does nothing with `s` as it is ("Used by evsm4 only."), or "" when it applies.
std::string notApplicableReason(const Settings& s, std::string_view path);

// The fields of the table that change the result of `s`, in table order.
std::vector<const FieldInfo*> applicableFields(const Settings& s);

// applicableFields minus what is not a shadow setting (scene, camera, light, output, path,
// measure, notes, and cascades.casterCulling, which changes the cost but not the image): the
// space a tuner searches for these settings.
std::vector<const FieldInfo*> tunableFields(const Settings& s);

// True when cascades.storage `storage` can hold the maps filter.kind `kind` samples.
bool storageSupports(FilterKind kind, CascadeStorage storage);

}  // namespace st
