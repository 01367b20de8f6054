#include <fstream>
#include <sstream>

#include "particles/scenefile.h"

namespace particles {

SceneDef loadScene(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec))
    throw SceneError(name + ": cannot open (a directory)");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw SceneError(name + ": cannot open");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw SceneError(name + ": cannot read");
  return parseScene(text.str(), name);
}

}  // namespace particles
