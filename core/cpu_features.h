// What the CPU can run beyond the baseline the project is compiled for (x86-64: SSE2), so that
// hot loops can pick a wider kernel at run time and still run everywhere.
#pragma once

namespace voltree {

// AVX2 and FMA (x86 since 2013); false on other architectures.
bool CpuHasAvx2Fma();

}  // namespace voltree
