// An engine using shadowtune's cascade math: practical split distances for a camera.
//   csm_consumer [near far count lambda]   prints "z0 z1 ... zN" (view depths, metres)
#include "renderer/csm/splits.h"

#include <cstdio>
#include <cstdlib>
#include <exception>

int main(int argc, char** argv) {
    st::csm::SplitParams p;  // scheme = Practical
    if (argc == 5) {
        p.nearPlane = std::strtof(argv[1], nullptr), p.farPlane = std::strtof(argv[2], nullptr);
        p.count = std::atoi(argv[3]), p.lambda = std::strtof(argv[4], nullptr);
    }
    try {
        for (float z : st::csm::computeSplits(p)) std::printf("%.6g ", z);
        std::printf("\n");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "csm_consumer: %s\n", e.what());
        return 1;
    }
}
