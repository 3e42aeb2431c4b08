#include "ui/layout_dump.h"

#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace coilsim::ui {
namespace {

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char esc[8];
      std::snprintf(esc, sizeof esc, "\\u%04x", c);
      out += esc;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

}  // namespace

std::string LayoutDump::pathFromEnvironment() {
  const char* p = std::getenv("COILSIM_LAYOUT_DUMP");
  return p ? p : "";
}

void LayoutDump::begin(float width, float height) {
  width_ = width, height_ = height;
  items_.clear();
  facts_.clear();
}

void LayoutDump::markLastItem(const char* name) {
  if (!enabled()) return;
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  mark(name, a.x, a.y, b.x, b.y);
}

void LayoutDump::mark(const char* name, float x0, float y0, float x1, float y1) {
  if (enabled()) items_.push_back({name, x0, y0, x1, y1});
}

void LayoutDump::fact(const char* name, double value) {
  if (!enabled()) return;
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", std::isfinite(value) ? value : 0.0);
  facts_.emplace_back(name, text);
}

void LayoutDump::fact(const char* name, bool value) {
  if (enabled()) facts_.emplace_back(name, value ? "true" : "false");
}

void LayoutDump::fact(const char* name, const std::string& value) {
  if (enabled()) facts_.emplace_back(name, quoted(value));
}

bool LayoutDump::write(std::string& error) const {
  if (!enabled()) return true;
  std::string text = "{\n  \"window\": [" + std::to_string(width_) + ", " + std::to_string(height_) + "],\n";
  for (const auto& [name, value] : facts_) text += "  " + quoted(name) + ": " + value + ",\n";
  text += "  \"items\": {";
  for (size_t i = 0; i < items_.size(); ++i) {
    const Item& it = items_[i];
    char rect[128];
    std::snprintf(rect, sizeof rect, "[%.1f, %.1f, %.1f, %.1f]", it.x0, it.y0, it.x1, it.y1);
    text += (i ? ",\n    " : "\n    ") + quoted(it.name) + ": " + rect;
  }
  text += "\n  }\n}\n";
  const std::string tmp = path_ + ".tmp";
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) {
    error = "cannot write the layout dump " + tmp;
    return false;
  }
  const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  if (std::fclose(f) != 0 || !ok || std::rename(tmp.c_str(), path_.c_str()) != 0) {
    error = "cannot write the layout dump " + path_;
    return false;
  }
  return true;
}

}  // namespace coilsim::ui
