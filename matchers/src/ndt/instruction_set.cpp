#include "ndt/instruction_set.hpp"

namespace sextant {

bool instruction_set_available(InstructionSet isa) {
#if SEXTANT_HAVE_AVX2
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return isa == InstructionSet::kBaseline || avx2;
#else
  return isa == InstructionSet::kBaseline;
#endif
}

InstructionSet best_instruction_set() {
  return instruction_set_available(InstructionSet::kAvx2) ? InstructionSet::kAvx2 : InstructionSet::kBaseline;
}

bool runs_avx2(InstructionSet isa) {
  return isa == InstructionSet::kAvx2 && SEXTANT_HAVE_AVX2 && instruction_set_available(isa);
}

}  // namespace sextant
