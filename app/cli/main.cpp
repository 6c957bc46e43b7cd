#include "common/version.h"

#include <cstring>
#include <iostream>

int main(int argc, char **argv)
{
    if (argc > 1 && std::strcmp(argv[1], "--version") == 0) {
        std::cout << "stratamesh-cli " << STRATAMESH_VERSION << "\n";
        return 0;
    }
    std::cerr << "usage: stratamesh-cli --version\n";
    return 2;
}
