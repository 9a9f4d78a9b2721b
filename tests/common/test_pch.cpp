// The one source of sextant_test_pch, the target that builds tests/common/test_pch.hpp once for all
// test executables (they reuse it through target_precompile_headers(... REUSE_FROM ...)).
