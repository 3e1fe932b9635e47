// PageMap (report.hpp): the map's part of the page, made once.
#include "parts.hpp"

#include "railodd/xodr_check/map_lines.hpp"

namespace railodd::report {

PageMap::State::State(xodr_check::MapLines lines)
    : map(std::move(lines)), frame(map.geo_reference, map.file), roads(map, frame) {}

PageMap::PageMap(const xodr::Map& map, const std::filesystem::path& file)
    : state_(std::make_unique<State>(detail::map_lines_of(map, file.string()))) {}

PageMap::PageMap(const std::filesystem::path& map_xodr)
    : state_(std::make_unique<State>(xodr_check::read_map_lines(map_xodr))) {}

PageMap::~PageMap() = default;

} // namespace railodd::report
