#include "tune/tune_holdout.h"

#include <algorithm>

namespace st::tune {

HeldOutVerdict heldOutVerdict(const HeldOutScore& input, const std::vector<HeldOutScore>& references,
                              const HeldOutScore& tuned) {
    const HeldOutScore* base = &input;
    if (!references.empty())
        base = &*std::min_element(references.begin(), references.end(),
                                  [](const HeldOutScore& a, const HeldOutScore& b) { return a.tuned < b.tuned; });
    HeldOutVerdict v;
    v.baseline = base->name;
    v.gainTuned = base->tuned - tuned.tuned;
    v.gainHeldOut = base->heldOut - tuned.heldOut;
    // Gain g > 0 must keep g/2; a loss (g < 0) may grow to 2g; g = 0 may not turn into a loss.
    v.judged = base->heldOut > 0.0 || tuned.heldOut > 0.0;
    v.holds = !v.judged || v.gainHeldOut >= std::min(0.5 * v.gainTuned, 2.0 * v.gainTuned);
    return v;
}

}  // namespace st::tune
