#pragma once
#include <string_view>

namespace amp::world {

// Where a COLLADA document has an index list (<p>, <v>, <vcount> or <h>) holding anything but
// digits and whitespace: a short quote of it, or empty when every list is clean. assimp 5.2's
// COLLADA parser does not advance past such a character and grows its index buffer until
// std::bad_alloc (minutes for a 1.5 kB file; found by fuzzing), so load_mesh refuses the file
// before handing it over.
std::string_view bad_collada_index_list(std::string_view document);

}  // namespace amp::world
