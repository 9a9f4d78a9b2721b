#pragma once
// The YAML side of core (target Sextant::core_yaml): the libraries take plain settings structs;
// each module's `sextant/<module>/yaml.hpp` (target Sextant::<module>_yaml) reads them from YAML
// with the SettingsReader below, whose errors name the file, the line and the key.
#include "sextant/core/settings_reader.hpp"
