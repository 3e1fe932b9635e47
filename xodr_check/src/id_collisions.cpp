// Road and junction ids share one space for some readers: CARLA's loader
// decides whether a link's elementId is a road or a junction by asking whether
// a road with that id exists and never reads elementType, so a junction whose
// id is also a road's id loses every link into it. The standard keeps the two
// id spaces apart only through elementType; we ask for them to be disjoint.
#include "checks.hpp"

#include <cstddef>
#include <string>

namespace railodd::xodr_check {

namespace {

// Road links naming the junction: the links such a reader would take for links to the road.
std::size_t links_into(const Document& doc, const std::string& junction_id) {
    std::size_t n = 0;
    for (const Road& r : doc.roads) {
        for (const Link* l : {&r.predecessor, &r.successor}) {
            n += l->present && l->element_type == "junction" && l->element_id == junction_id ? 1 : 0;
        }
    }
    return n;
}

} // namespace

void check_id_collisions(Context& ctx) {
    for (const Junction& j : ctx.doc.junctions) {
        const Road* road = ctx.doc.road(j.id);
        if (!road) {
            continue;
        }
        const std::string named = road->name.empty() ? "" : " ('" + road->name + "')";
        ctx.error("junction", j.id, nan, "id_collision",
                  "junction id '" + j.id + "' is also the id of road " + road->id + named + ": the " +
                      std::to_string(links_into(ctx.doc, j.id)) + " link(s) naming this junction read as links to road " +
                      road->id + " in a reader that resolves elementId by road id first (CARLA)");
    }
}

} // namespace railodd::xodr_check
