#pragma once
// Why the tuned preset is better, change by change (docs/tuning.md#explain): each change from the
// input preset is measured alone (the input with only that change) and in context (the tuned
// preset without it), by the same evaluator the search used. No GL.
#include "tune/tune_search.h"
#include "tune/tune_space.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace st::tune {

struct Explained {
    Change change;
    std::string label;       // the field's label and unit: "Shadow distance (m)"
    Evaluation alone;        // input + this change
    Evaluation without;      // tuned - this change
    std::string line;        // "Shadow distance 0 -> 250 m: alone it cuts the error by 40 % (...) at 12 % more cost; ..."
    std::string worse;       // "Alone, acne rises to 9.2 % from the input's 5.2 %." (empty: nothing worse)
    // Fields set with it, first, as the change means nothing without them: manual splits come
    // with the manual scheme (and the tuned count, when theirs differs from the input's).
    std::vector<std::pair<std::string, nlohmann::json>> with;
};

struct Explanation {
    std::string objective;  // its label: "filtered error vs the sun's disc"
    Evaluation input, tuned;
    std::vector<Explained> changes;
    // Artifact figures the tuned preset has more of than the input, each a sentence ("False shadow
    // rises from 0.071 % to 0.207 % of sun-facing pixels.").
    std::vector<std::string> worse;
};

// Measures 2 x changes settings through `evaluate` (it journals them like the search's).
Explanation explain(const Settings& input, const Evaluation& inputEval, const Settings& tuned,
                    const Evaluation& tunedEval, const std::string& objectiveChoice, const Evaluator& evaluate);

nlohmann::ordered_json toJson(const Explanation& e);
std::string toMarkdown(const Explanation& e, const std::string& title);

}  // namespace st::tune
