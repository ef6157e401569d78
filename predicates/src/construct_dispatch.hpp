// exidel (private): which Two-Product circumcenter()'s double-word stage uses.
//
// True when the processor has a fused multiply-add (detected once), which the stage then
// uses for its exact products; false selects Dekker's split. Both are exact, so the
// results are identical; tests flip it to run both.
#pragma once

namespace exidel::detail {

bool& circumcenter_use_fma() noexcept;

}  // namespace exidel::detail
