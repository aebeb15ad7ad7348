#include "biphasic/io/config.hpp"
