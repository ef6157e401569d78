// exidel (private): whether the batched predicates use their AVX2 filters.
//
// True when the processor has AVX2 (detected once); tests set it to false to run the
// scalar loops on the same machine. Both give the adaptive kernel's exact signs.
#pragma once

namespace exidel::detail {

bool& batch_use_avx2() noexcept;

}  // namespace exidel::detail
