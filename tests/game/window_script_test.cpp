// The demo window's --script steps: what each one parses to, and one-line errors.
#include "game/window_script.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace qlight::game {
namespace {

TEST(WindowScript, ParsesEachAction) {
  ScriptStep resize = parseScriptStep("12:resize=640x360");
  EXPECT_EQ(resize.frame, 12u);
  EXPECT_EQ(resize.action, ScriptStep::Action::Resize);
  EXPECT_EQ(resize.width, 640u);
  EXPECT_EQ(resize.height, 360u);
  ScriptStep vsync = parseScriptStep("0:vsync=on");
  EXPECT_EQ(vsync.action, ScriptStep::Action::Vsync);
  EXPECT_TRUE(vsync.on);
  EXPECT_FALSE(parseScriptStep("3:vsync=off").on);
  ScriptStep load = parseScriptStep("5:load=/tmp/a:b=c.json");  // the rest is the path
  EXPECT_EQ(load.action, ScriptStep::Action::Load);
  EXPECT_EQ(load.path, "/tmp/a:b=c.json");
  EXPECT_EQ(parseScriptStep("6:save=s.json").action, ScriptStep::Action::Save);
  EXPECT_TRUE(parseScriptStep("7:points=on").on);
  EXPECT_EQ(parseScriptStep("7:points=on").action, ScriptStep::Action::Points);
  EXPECT_FALSE(parseScriptStep("8:denoise=off").on);
  EXPECT_EQ(parseScriptStep("8:denoise=off").action, ScriptStep::Action::Denoise);
  EXPECT_EQ(parseScriptStep("9:panel=off").action, ScriptStep::Action::Panel);
  ScriptStep capture = parseScriptStep("9:capture=/tmp/w.png");
  EXPECT_EQ(capture.action, ScriptStep::Action::Capture);
  EXPECT_EQ(capture.path, "/tmp/w.png");
}

TEST(WindowScript, RefusesMalformedSteps) {
  for (const char* bad : {"", "resize=640x360", "x:resize=640x360", "-1:vsync=on", "3:vsync",
                          "3:vsync=maybe", "3:resize=640", "3:resize=0x10", "3:resize=64x10x",
                          "3:load=", "3:jump=1", "4:points=yes", "4:denoise", "4:capture="}) {
    try {
      parseScriptStep(bad);
      ADD_FAILURE() << bad << " parsed";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("--script ") + bad), std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace qlight::game
