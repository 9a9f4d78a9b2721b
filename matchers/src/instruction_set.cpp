#include "instruction_set.hpp"

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

}  // namespace sextant
