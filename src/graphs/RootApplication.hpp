#pragma once

namespace physim {

/// Makes sure ROOT's application object exists: without one ROOT draws every canvas off screen. ROOT allows one
/// per process and cannot delete it before exit, so it is made on the first call (the first live graphs) and
/// kept for the program's life, as the paper's GraphsManager kept its own. Returns false when ROOT has no
/// display to open windows on (it is in batch mode).
bool ensureRootApplication();

}  // namespace physim
