#include "scene/Mesh.h"

namespace manylights {

Bounds Mesh::bounds() const
{
    Bounds b;
    for (const Vertex& v : vertices)
        b.extend(v.position);
    return b;
}

}  // namespace manylights
