#pragma once
// The core's types as the shared kernel's plain structs (ContinuousKernel.hpp), and a continuous batch's arrays as
// the kernel's raw views. Internal: the core and the CUDA layer call these; users fill a ContinuousBatch instead.

#include "ContinuousKernel.hpp"

#include "physim/core/ContinuousBatch.hpp"
#include "physim/core/Geometry.hpp"
#include "physim/core/TimeOfImpact.hpp"

namespace physim {

/// Raw pointers into the batch's and the result's arrays (result must already be resized), for a kernel.
kernel::BatchView viewOf(const ContinuousBatch& batch);
kernel::ResultView viewOf(ContinuousBatchResult& result);

/// The kernel's plain structs from the core's types.
kernel::Shape toKernel(const Geometry& g);
kernel::Motion toKernel(const Sweep& s);
kernel::Xf toKernel(const Transform& xf);

}  // namespace physim
