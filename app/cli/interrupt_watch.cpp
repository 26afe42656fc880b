#include "app/cli/interrupt_watch.h"

#include <csignal>

namespace st::app {
namespace {
volatile std::sig_atomic_t g_interrupted = 0;

extern "C" void onInterrupt(int) {
    if (g_interrupted) {
        std::signal(SIGINT, SIG_DFL);
        std::raise(SIGINT);
    }
    g_interrupted = 1;
}
}  // namespace

InterruptWatch::InterruptWatch() {
    g_interrupted = 0;
    std::signal(SIGINT, onInterrupt);
}
InterruptWatch::~InterruptWatch() { std::signal(SIGINT, SIG_DFL); }
bool InterruptWatch::requested() { return g_interrupted != 0; }

}  // namespace st::app
