#include "numerics/Fragments.hpp"

#include <gtest/gtest.h>

#include <vector>

using namespace mfwave;

namespace {

Coordinates<2> cloud(const std::vector<std::pair<Real, Real>>& points) {
  Coordinates<2> c;
  for (const auto& [x, y] : points) {
    c[0].push_back(x);
    c[1].push_back(y);
  }
  return c;
}

}  // namespace

// Two rows of particles a spacing apart, far from each other, and one stray: three fragments,
// largest first, each particle labelled with its own.
TEST(Fragments, LabelsConnectedPiecesLargestFirst) {
  std::vector<std::pair<Real, Real>> points;
  for (int i = 0; i < 5; ++i) points.push_back({0.1 * i, 0.0});   // 5 in a row
  for (int i = 0; i < 3; ++i) points.push_back({5 + 0.1 * i, 0.0});  // 3 in a row
  points.push_back({10, 10});                                        // a stray
  const Fragments f = findFragments(cloud(points), 0.15);
  EXPECT_EQ(f.count(), 3);
  EXPECT_EQ(f.sizes, (std::vector<Index>{5, 3, 1}));
  for (int i = 0; i < 5; ++i) EXPECT_EQ(f.label[static_cast<std::size_t>(i)], 0);
  for (int i = 5; i < 8; ++i) EXPECT_EQ(f.label[static_cast<std::size_t>(i)], 1);
  EXPECT_EQ(f.label[8], 2);
  EXPECT_EQ(f.particlesOutsideLargest(2), 1);
  EXPECT_EQ(findFragments(cloud(points), 20).count(), 1);  // a long link joins everything
}

// The links of a row at the start; stretching the middle gap tears exactly one.
TEST(Fragments, CountsTornLinks) {
  Coordinates<2> row = cloud({{0, 0}, {0.1, 0}, {0.2, 0}, {0.3, 0}});
  const auto links = linkPairs(row, 0.15);
  EXPECT_EQ(links.size(), 3u);
  EXPECT_EQ(tornLinks(links, row, 0.15), 0);
  row[0][2] += 0.1;
  row[0][3] += 0.1;
  EXPECT_EQ(tornLinks(links, row, 0.15), 1);
}
