#include "RootApplication.hpp"

#include <TApplication.h>
#include <TROOT.h>

#include <cstdlib>

namespace physim {

bool ensureRootApplication() {
    // A program that made its own application object keeps it. Ours is never deleted: ROOT crashes deleting it
    // during exit, and a second one cannot be made (ROOT's gApplication points to it).
    static const TApplication* const application = [] {
        if (gApplication) return gApplication;
        const char* display = std::getenv("DISPLAY");
        if (display && *display) gROOT->SetBatch(kFALSE);  // a headless export earlier in the process set it
        auto* app = new TApplication("physim", nullptr, nullptr);
        app->SetReturnFromRun(kTRUE);  // the canvas menu's "Quit ROOT" then ends ROOT's loop, not the program
        return app;
    }();
    return application != nullptr && !gROOT->IsBatch();
}

}  // namespace physim
