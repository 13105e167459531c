#include "bullet_sim_core/gazebo_materials.h"

#include <map>

namespace bullet_sim {

std::optional<std::array<float, 4>> gazeboMaterialColour(const std::string& name) {
  // Diffuse colours of the common materials of Gazebo's gazebo.material.
  static const std::map<std::string, std::array<float, 4>> table = {
      {"Gazebo/Grey", {0.7f, 0.7f, 0.7f, 1}},         {"Gazebo/Gray", {0.7f, 0.7f, 0.7f, 1}},
      {"Gazebo/DarkGrey", {0.35f, 0.35f, 0.35f, 1}},  {"Gazebo/LightGrey", {0.85f, 0.85f, 0.85f, 1}},
      {"Gazebo/White", {1, 1, 1, 1}},                 {"Gazebo/Black", {0, 0, 0, 1}},
      {"Gazebo/FlatBlack", {0.1f, 0.1f, 0.1f, 1}},    {"Gazebo/Red", {1, 0, 0, 1}},
      {"Gazebo/RedBright", {0.87f, 0.26f, 0.07f, 1}}, {"Gazebo/Green", {0, 1, 0, 1}},
      {"Gazebo/Blue", {0, 0, 1, 1}},                  {"Gazebo/SkyBlue", {0.53f, 0.81f, 0.92f, 1}},
      {"Gazebo/Yellow", {1, 1, 0, 1}},                {"Gazebo/ZincYellow", {0.97f, 0.95f, 0.21f, 1}},
      {"Gazebo/DarkYellow", {0.7f, 0.7f, 0, 1}},      {"Gazebo/Purple", {1, 0, 1, 1}},
      {"Gazebo/Turquoise", {0, 1, 1, 1}},             {"Gazebo/Orange", {1, 0.51f, 0.05f, 1}},
      {"Gazebo/Indigo", {0.33f, 0, 0.5f, 1}},         {"Gazebo/Gold", {0.8f, 0.65f, 0.2f, 1}},
      {"Gazebo/Wood", {0.6f, 0.4f, 0.2f, 1}},         {"Gazebo/WoodFloor", {0.65f, 0.5f, 0.35f, 1}},
      {"Gazebo/Bricks", {0.6f, 0.3f, 0.2f, 1}},       {"Gazebo/PaintedWall", {0.9f, 0.9f, 0.85f, 1}},
      {"Gazebo/BlueTransparent", {0, 0, 1, 0.5f}},    {"Gazebo/GreenTransparent", {0, 1, 0, 0.5f}},
      {"Gazebo/RedTransparent", {1, 0, 0, 0.5f}},     {"Gazebo/GreyTransparent", {0.5f, 0.5f, 0.5f, 0.5f}},
      {"Gazebo/BlackTransparent", {0, 0, 0, 0.5f}},   {"Gazebo/Residential", {0.8f, 0.8f, 0.75f, 1}},
  };
  const auto it = table.find(name);
  if (it == table.end()) return std::nullopt;
  return it->second;
}

}  // namespace bullet_sim
