#pragma once
// Ctrl-C for the long headless commands (sweep, tune): the first SIGINT asks the run to stop after
// the item under way (everything finished is kept; the same command resumes); a second quits now.
namespace st::app {

class InterruptWatch {
public:
    InterruptWatch();   // installs the handler, clears the flag
    ~InterruptWatch();  // restores the default handler
    InterruptWatch(const InterruptWatch&) = delete;
    InterruptWatch& operator=(const InterruptWatch&) = delete;
    static bool requested();
};

}  // namespace st::app
