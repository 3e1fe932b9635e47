// util::CellGrid: items by cell in the order added, and queries that visit
// cells in a fixed order (x, then y), whatever the hash table's.
#include "railodd/util/cell_grid.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using railodd::util::CellGrid;

TEST(CellGrid, CellsFloorEveryCoordinateNegativeOnesToo) {
    const CellGrid<int> g(10.0);
    EXPECT_EQ(g.cell_of(0.0), 0);
    EXPECT_EQ(g.cell_of(9.999), 0);
    EXPECT_EQ(g.cell_of(10.0), 1);
    EXPECT_EQ(g.cell_of(-0.001), -1);
    EXPECT_EQ(g.cell_of(-10.0), -1);
    EXPECT_EQ(g.cell_of(-10.001), -2);
}

TEST(CellGrid, NearVisitsCellsByXThenYAndItemsInTheOrderAdded) {
    CellGrid<std::string> g(10.0);
    // Added in an order unlike the visit's, some at negative cells, many
    // cells to spread the hash table.
    for (int k = 0; k < 200; ++k) {
        g.add(100 + k, 100, "far");
    }
    g.add_point(15.0, -5.0, "x1 y-1 a");
    g.add_point(-5.0, 5.0, "x-1 y0");
    g.add_point(15.0, -5.0, "x1 y-1 b");
    g.add_point(5.0, 15.0, "x0 y1");
    g.add_point(5.0, -15.0, "x0 y-2"); // outside reach 1 of cell (0, 0)
    std::vector<std::string> seen;
    g.near(1.0, 1.0, 1, [&](const std::string& s) { seen.push_back(s); });
    EXPECT_EQ(seen, (std::vector<std::string>{"x-1 y0", "x0 y1", "x1 y-1 a", "x1 y-1 b"}));
}

TEST(CellGrid, ABoxFillsTheCellsItTouchesUnlessTooMany) {
    CellGrid<int> g(10.0);
    EXPECT_TRUE(g.add_box(-1.0, 5.0, 12.0, 25.0, 7)); // cells x -1..1, y 0..2
    int cells = 0;
    for (int cx = -3; cx <= 3; ++cx) {
        for (int cy = -3; cy <= 3; ++cy) {
            if (const auto* items = g.at(cx, cy)) {
                ++cells;
                EXPECT_EQ(*items, std::vector<int>{7});
            }
        }
    }
    EXPECT_EQ(cells, 9);
    EXPECT_FALSE(g.add_box(0.0, 0.0, 1000.0, 1000.0, 8, 100)); // 101 x 101 cells
    EXPECT_EQ(g.at(50, 50), nullptr);
    EXPECT_FALSE(g.empty());
    EXPECT_TRUE(CellGrid<int>(1.0).empty());
}
