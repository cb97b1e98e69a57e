#include "io/vtk/FrameOutputs.hpp"

#include <gtest/gtest.h>

using namespace mfwave;

// [output]'s picture keys become the renderer's options, the component by its index.
TEST(FrameOutputs, PngOptionsFollowTheOutputSection) {
  OutputSpec output;
  output.pngField = "displacement";
  output.pngComponent = "y";
  output.pngComponentIndex = 1;
  output.pngPointSize = 3.5;
  output.pngWidth = 640;
  output.pngHeight = 480;
  const PngOptions png = pngOptionsFor(output);
  EXPECT_EQ(png.field, "displacement");
  EXPECT_EQ(png.component, 1);
  EXPECT_DOUBLE_EQ(png.pointSize, 3.5);
  EXPECT_EQ(png.width, 640);
  EXPECT_EQ(png.height, 480);
  output.pngComponent = "magnitude";
  output.pngComponentIndex = -1;
  EXPECT_EQ(pngOptionsFor(output).component, PngOptions::magnitude);
}

TEST(FrameOutputs, ReportListsNothingForOutputsNotAsked) {
  const FrameOutputReport report = frameOutputReport<2>("case", std::nullopt, std::nullopt);
  EXPECT_TRUE(report.files.empty());
  EXPECT_TRUE(report.notes.empty());
}
