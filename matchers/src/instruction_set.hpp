#pragma once
// Internal: the instruction sets the hot loops are compiled for. On x86-64 each is compiled twice,
// for plain x86-64 (SSE2) and with AVX2, which the CPU chooses at run time; elsewhere only the
// baseline is. Every loop gives the same bits on both (its tests check it): the choice is speed only.

namespace sextant {

enum class InstructionSet { kBaseline, kAvx2 };
/// True when this build has `isa` and the CPU runs it.
bool instruction_set_available(InstructionSet isa);
/// The fastest available one.
InstructionSet best_instruction_set();

}  // namespace sextant
