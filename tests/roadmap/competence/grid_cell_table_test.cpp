#include "amp/roadmap/competence/grid_cell_table.hpp"

#include <map>
#include <random>

#include <gtest/gtest.h>

namespace amp::roadmap {
namespace {

GridCellTable::Cell cell(std::int16_t x, std::int16_t y, std::int16_t z = 0) {
  GridCellTable::Cell c{};
  c[0] = x;
  c[1] = y;
  c[2] = z;
  return c;
}

TEST(GridCellTable, IdsFollowInsertionOrder) {
  GridCellTable table(2, 4);
  table.clear();
  EXPECT_EQ(table.find(cell(0, 0)), -1);
  EXPECT_EQ(table.insert(cell(0, 0)), 0);
  EXPECT_EQ(table.insert(cell(1, 0)), 1);
  EXPECT_EQ(table.insert(cell(-1, 5)), 2);
  EXPECT_EQ(table.find(cell(1, 0)), 1);
  EXPECT_EQ(table.find(cell(-1, 5)), 2);
  EXPECT_EQ(table.find(cell(5, -1)), -1);
  EXPECT_EQ(table.size(), 3u);
}

TEST(GridCellTable, ClearForgetsEveryCellAndKeepsTheSlots) {
  GridCellTable table(3, 8);
  table.clear();
  for (std::int16_t i = 0; i < 100; ++i) table.insert(cell(i, static_cast<std::int16_t>(-i), 1));
  const std::size_t slots = table.slots();
  EXPECT_GE(slots, 200u);  // at most half full
  table.clear();
  EXPECT_EQ(table.size(), 0u);
  EXPECT_EQ(table.slots(), slots);
  for (std::int16_t i = 0; i < 100; ++i) EXPECT_EQ(table.find(cell(i, static_cast<std::int16_t>(-i), 1)), -1);
  EXPECT_EQ(table.insert(cell(7, -7, 1)), 0);
  EXPECT_EQ(table.find(cell(7, -7, 1)), 0);
}

// Against std::map on random cells over many searches: growth, probing and generations together.
TEST(GridCellTable, AgreesWithAnOrderedMap) {
  GridCellTable table(3, 2);
  std::mt19937 gen(7);
  std::uniform_int_distribution<int> coord(-6, 6);
  for (int search = 0; search < 50; ++search) {
    table.clear();
    std::map<GridCellTable::Cell, std::int32_t> truth;
    for (int step = 0; step < 400; ++step) {
      const auto c = cell(static_cast<std::int16_t>(coord(gen)), static_cast<std::int16_t>(coord(gen)),
                          static_cast<std::int16_t>(coord(gen)));
      const auto it = truth.find(c);
      const std::int32_t found = table.find(c);
      if (it == truth.end()) {
        ASSERT_EQ(found, -1);
        const std::int32_t id = table.insert(c);
        ASSERT_EQ(id, static_cast<std::int32_t>(truth.size()));
        truth.emplace(c, id);
      } else {
        ASSERT_EQ(found, it->second);
      }
    }
    ASSERT_EQ(table.size(), truth.size());
  }
}

}  // namespace
}  // namespace amp::roadmap
