#pragma once
#include <string>
#include <string_view>

namespace amp::world {

// Why a COLLADA document must not be handed to assimp 5.2, or empty when it may. Each check is a
// defect of assimp's COLLADA importer that fuzzing found (docs/fuzzing.md):
//  - an index list (<p>, <v>, <vcount>, <h>) holding anything but digits and whitespace: the parser
//    does not advance past the character and grows its index buffer until std::bad_alloc (minutes
//    for a 1.5 kB file);
//  - an <accessor> that reaches past its data array (<float_array> and the like, whose `count` is
//    what assimp stores; a missing count stores nothing): assimp indexes the array unchecked and
//    dereferences null or reads past its end.
// The screen reads tags and attributes as written. What it cannot read plainly (a count that is not
// a decimal number, a source that names no array in the document) it refuses: a well-formed file
// never needs it.
std::string collada_refusal(std::string_view document);

}  // namespace amp::world
