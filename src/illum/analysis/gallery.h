// The material gallery: one sphere per reflection model of the registry (default parameters), in a grid
// over a grey checkerboard floor, lit by a rectangular area light and a constant environment.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "illum/render/scene.h"

namespace illum {

struct GalleryEntry {
    std::string model;
    std::map<std::string, std::string> params;
};

// The models shown, in grid order (left to right, top to bottom).
std::vector<GalleryEntry> gallery_entries();
std::unique_ptr<Scene> make_gallery_scene(int width, int height);

} // namespace illum
