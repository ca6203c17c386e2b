#include "parksim/renders/plots/FigureSelection.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "RenderTestUtil.h"
#include "parksim/core/io/Error.h"
#include "parksim/renders/plots/Figures.h"

namespace parksim {
namespace {

TEST(FigureSelectionTest, ParsesAllNoneAndListsWithRepeats) {
  EXPECT_EQ(FigureSelection::parse("all").toString(), "all");
  EXPECT_TRUE(FigureSelection::parse("none").empty());
  const FigureSelection s = FigureSelection::parse("plan, lot_map,plan");
  EXPECT_TRUE(s.contains("lot_map"));
  EXPECT_TRUE(s.contains("plan"));
  EXPECT_TRUE(s.contains("plan_rrt-star"));  // "plan" stands for every plan_<name>
  EXPECT_FALSE(s.contains("steering"));
  EXPECT_FALSE(s.contains("bogus"));
  EXPECT_EQ(s.toString(), "lot_map,plan");  // in writing order, once each
  EXPECT_EQ(FigureSelection::parse(s.toString()).chosen, s.chosen);
  for (std::string_view name : kFigureNames) {
    EXPECT_TRUE(FigureSelection::all().contains(name)) << name;
    EXPECT_FALSE(FigureSelection::none().contains(name)) << name;
    EXPECT_EQ(FigureSelection::parse(std::string(name)).toString(), name);
  }
}

TEST(FigureSelectionTest, UnknownOrEmptyNamesAreRefusedWithTheValidNames) {
  for (const char* text : {"lot_map,bogus", "", "lot_map,", "Lot_Map", "plan_rrt"}) {
    try {
      FigureSelection::parse(text);
      ADD_FAILURE() << "accepted '" << text << "'";
    } catch (const Error& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      for (std::string_view name : kFigureNames) {
        EXPECT_NE(message.find(name), std::string::npos) << message;
      }
    }
  }
}

TEST(FigureSelectionTest, WriteFiguresWritesTheChosenOnesOnly) {
  const Scenario s = rendertest::testLot();
  FigureDef def;
  def.width_px = 120;
  def.height_px = 80;
  def.msaa_samples = 1;
  def.cspace_slices = 2;
  FigureInputs inputs;
  PlanFigure plan;
  plan.name = "a";
  plan.trajectory = rendertest::sampleDrive(s.robot, s.start);
  inputs.plans = {plan, plan};
  inputs.plans[1].name = "b";
  const std::string dir = rendertest::outputDir("FigureSelectionTest");
  def.figures = FigureSelection::parse("plan,lot_map");
  EXPECT_EQ(writeFigures(s, inputs, def, dir + "/some"),
            (std::vector<std::string>{dir + "/some/lot_map.png", dir + "/some/plan_a.png",
                                      dir + "/some/plan_b.png"}));
  int files = 0;
  for ([[maybe_unused]] const auto& f : std::filesystem::directory_iterator(dir + "/some")) ++files;
  EXPECT_EQ(files, 3);
  def.figures = FigureSelection::none();
  EXPECT_TRUE(writeFigures(s, inputs, def, dir + "/none").empty());
  EXPECT_FALSE(std::filesystem::exists(dir + "/none"));
}

}  // namespace
}  // namespace parksim
