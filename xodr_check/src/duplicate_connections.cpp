// Duplicate junction connections. OpenDRIVE 1.7 and 1.8 represent each
// connecting road by exactly one <connection>; readers that list a connecting
// road once per connection naming it (CARLA) get its successor twice. In a 1.8
// direct junction one linkedRoad may be reached from several incoming roads,
// so there only a repeated (incomingRoad, linkedRoad) pair is a duplicate.
#include "checks.hpp"

#include <map>
#include <string>
#include <utility>

namespace railodd::xodr_check {

namespace {

void report(Context& ctx, const Junction& j, const Connection& first, const Connection& again) {
    const bool direct = j.type == "direct";
    const std::string role = direct ? "linked road " : "connecting road ";
    std::string what;
    if (first.incoming == again.incoming) {
        what = "repeats connection " + first.id + " (incoming road " + again.incoming + ", " + role +
               again.connecting + ")";
    } else {
        what = "names " + role + again.connecting + " again (from incoming road " + again.incoming +
               "; connection " + first.id + " names it from incoming road " + first.incoming + ")";
    }
    const std::string why = direct ? ": the same incoming and linked road twice"
                                   : ": each connecting road belongs in exactly one connection, and a reader that "
                                     "lists it once per connection (CARLA) gets its successor twice";
    ctx.error("junction", j.id, nan, "duplicate_connection", "connection " + again.id + " " + what + why);
}

} // namespace

void check_duplicate_connections(Context& ctx) {
    for (const Junction& j : ctx.doc.junctions) {
        const bool direct = j.type == "direct";
        // Key: the connecting road, or (incoming, linked) in a direct junction.
        std::map<std::pair<std::string, std::string>, const Connection*> seen;
        for (const Connection& con : j.connections) {
            const auto key = std::pair{direct ? con.incoming : std::string{}, con.connecting};
            const auto [it, fresh] = seen.emplace(key, &con);
            if (!fresh) {
                report(ctx, j, *it->second, con);
            }
        }
    }
}

} // namespace railodd::xodr_check
