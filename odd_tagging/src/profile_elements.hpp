#pragma once
// The elements of odd_profile.json (profile.hpp holds the format). Format 2
// writes them as a table: each distinct element kind (path and id) once in
// "element_kinds", each element as one row of "element_columns". Format 1
// (one object per element, every key repeated) is still read.
#include "railodd/odd/profile.hpp"

#include <cstddef>
#include <deque>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace railodd::odd::profile_elements {

// Positions are written to the millimetre: chainage and s are metres along a
// fitted centreline whose own accuracy is centimetres, and the 17 digits of
// a double made up a quarter of the file.
double metres(double value);

// The rows' columns, written to the file so that a reader can check them.
const std::vector<std::string>& columns();

// The distinct kinds ([path, id]) in order of first use, as the elements
// come (a profile written a batch at a time numbers them the same way).
class KindIndex {
public:
    std::size_t of(const TaggedElement& e); // the element's kind's index, added on first use
    const std::vector<std::pair<std::string, std::string>>& list() const { return list_; }

private:
    std::vector<std::pair<std::string, std::string>> list_;
    std::unordered_map<std::string, std::size_t> index_; // by path and id, which a taxonomy pairs one to one
};

// The same over a whole profile: the kinds, and each element's index into them.
struct Kinds {
    std::vector<std::pair<std::string, std::string>> list;
    std::vector<std::size_t> of;
};
Kinds kinds_of(const std::deque<TaggedElement>& elements);

// One element's row as compact JSON text, and the same as a tree (to_json).
void append_row(std::string& out, const TaggedElement& e, std::size_t kind);
nlohmann::ordered_json row_json(const TaggedElement& e, std::size_t kind);

// The elements of a format 2 document ("element_kinds", "element_columns",
// "elements") and of a format 1 document ("elements" as objects). Throw
// std::invalid_argument naming the element and the key.
std::deque<TaggedElement> from_rows(const nlohmann::json& doc);
// One at a time, for a reader that streams the rows (read_profile): the kind
// list of "element_kinds", the check of "element_columns", then each row or
// (format 1) each element object, `where` naming it in errors.
using KindList = std::vector<std::pair<std::string, std::string>>;
KindList kinds_from(const nlohmann::ordered_json& kinds);
void check_columns(const nlohmann::ordered_json& columns);
TaggedElement from_row(const nlohmann::ordered_json& row, const KindList& kinds, const std::string& where);
TaggedElement from_object(const nlohmann::ordered_json& element, const std::string& where);
std::deque<TaggedElement> from_rows(const nlohmann::ordered_json& doc);
std::deque<TaggedElement> from_objects(const nlohmann::json& doc);
std::deque<TaggedElement> from_objects(const nlohmann::ordered_json& doc);

} // namespace railodd::odd::profile_elements
