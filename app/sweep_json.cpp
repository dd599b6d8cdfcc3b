#include "app/sweep_json.h"

#include <nlohmann/json.hpp>

namespace shadowlab {

std::string formatSweepJson(const SweepResults& results) {
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const SweepRow& r : results.rows) {
        nlohmann::ordered_json stats = nlohmann::ordered_json::object();
        for (const TechniqueStat& s : r.stats) stats[s.name] = s.value;
        rows.push_back({{"technique", r.technique},
                        {"reference", r.reference},
                        {"settings", r.settings},
                        {"threads", r.threads},
                        {"median_ms", r.medianMs},
                        {"min_ms", r.minMs},
                        {"errors", nlohmann::ordered_json::parse(formatJson(r.errors))},
                        {"stats", stats}});
    }
    nlohmann::ordered_json j;
    j["scene"] = results.scene;
    j["rows"] = rows;
    return j.dump(2) + "\n";
}

}  // namespace shadowlab
