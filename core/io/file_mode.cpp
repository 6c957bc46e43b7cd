#include "io/file_mode.h"

#include <cstring>
#include <fstream>

namespace stratamesh {

std::string systemError(int error)
{
    return std::strerror(error);
}

mode_t currentUmask()
{
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("Umask:", 0) == 0)
            return static_cast<mode_t>(std::stoul(line.substr(6), nullptr, 8));
    return 022;
}

} // namespace stratamesh
