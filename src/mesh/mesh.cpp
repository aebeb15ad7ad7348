#include "biphasic/mesh/mesh.hpp"
