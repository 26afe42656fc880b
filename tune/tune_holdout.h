#pragma once
// Does a tune hold on the views it did not see (docs/tuning.md#views)? No GL.
#include <string>
#include <vector>

namespace st::tune {

// One contender's objective error on the tuned and on the held-out views.
struct HeldOutScore {
    std::string name;  // "input", a reference's name
    double tuned = 0, heldOut = 0;
};

struct HeldOutVerdict {
    std::string baseline;  // what the tuned preset is compared with
    double gainTuned = 0, gainHeldOut = 0;  // baseline error - tuned preset's error, per view set
    bool holds = true;
    // False when the held-out views show no error for the baseline nor the tuned preset (a view
    // with nothing shadowed, as living-room's orbits): there is no gain to keep, so nothing is
    // judged and the tune is not flagged.
    bool judged = true;
};

// The baseline is the best (least error on the tuned views) of the references, or the input when
// there are none: the tune's claim is "better than what you would otherwise ship", and the input may
// be over the budget. The tune holds when the held-out views keep at least half of the gain on the
// tuned views; a tune that lost to the baseline holds when it loses no more than twice as much there.
HeldOutVerdict heldOutVerdict(const HeldOutScore& input, const std::vector<HeldOutScore>& references,
                              const HeldOutScore& tuned);

}  // namespace st::tune
