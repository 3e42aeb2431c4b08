#pragma once
// Where the window's controls are on screen, for tests that drive the real
// window under Xvfb (set COILSIM_LAYOUT_DUMP=FILE): each marked control's
// rectangle in window units (pixels without HiDPI, origin top left), the
// window size, and facts about the window's state (a confirmation open,
// the help shown, the coil's deployed length). A test checks from it that
// the device controls lie inside the window, and waits on it for the state
// its next key needs. Written every frame, atomically (temporary + rename).
#include <string>
#include <utility>
#include <vector>

namespace coilsim::ui {

class LayoutDump {
 public:
  // The path from COILSIM_LAYOUT_DUMP; empty (and then every call is cheap
  // and does nothing) when it is not set.
  static std::string pathFromEnvironment();

  explicit LayoutDump(std::string path) : path_(std::move(path)) {}
  bool enabled() const { return !path_.empty(); }
  // Starts a frame: forgets the last one's items and facts.
  void begin(float width, float height);
  // The last ImGui item's rectangle under `name` (call right after the item).
  void markLastItem(const char* name);
  void mark(const char* name, float x0, float y0, float x1, float y1);
  void fact(const char* name, double value);
  void fact(const char* name, bool value);
  void fact(const char* name, const std::string& value);
  // Writes the frame as JSON. Returns false with the reason in `error`.
  bool write(std::string& error) const;

 private:
  struct Item {
    std::string name;
    float x0, y0, x1, y1;
  };
  std::string path_;
  float width_ = 0, height_ = 0;
  std::vector<Item> items_;
  std::vector<std::pair<std::string, std::string>> facts_;  // name, JSON value
};

}  // namespace coilsim::ui
