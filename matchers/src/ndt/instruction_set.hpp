#pragma once
// Internal: the instruction sets the hot loops are compiled for. On x86-64 each is compiled twice,
// for plain x86-64 (SSE2) and with AVX2, which the CPU chooses at run time; elsewhere only the
// baseline is. Every loop gives the same bits on both (its tests check it): the choice is speed only.

/// 1 where this build compiles the AVX2 paths (x86-64 with GCC or Clang), else 0.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define SEXTANT_HAVE_AVX2 1
#else
#define SEXTANT_HAVE_AVX2 0
#endif

namespace sextant {

enum class InstructionSet { kBaseline, kAvx2 };
/// True when this build has `isa` and the CPU runs it.
bool instruction_set_available(InstructionSet isa);
/// The fastest available one.
InstructionSet best_instruction_set();
/// True when `isa` is AVX2 and this build and the CPU both have it: where a dispatch takes its AVX2 path.
bool runs_avx2(InstructionSet isa);

}  // namespace sextant
