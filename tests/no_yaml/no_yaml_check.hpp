#pragma once
// Included after every public header of the plain libraries (all_library_headers.cpp, generated):
// none of them may have pulled in yaml-cpp. Its headers sit in /usr/include, so an include would
// compile; its include guards and export macro tell.
#if defined(YAML_H_62B23520_7C8E_11DE_8A39_0800200C9A66) || defined(YAML_CPP_API) || \
    defined(NODE_NODE_H_62B23520_7C8E_11DE_8A39_0800200C9A66)
#error "a public header of a plain Sextant library includes yaml-cpp; YAML belongs in <module>/yaml.hpp"
#endif
