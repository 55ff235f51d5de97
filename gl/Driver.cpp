#include "gl/Driver.h"

#include <epoxy/gl.h>

namespace manylights::gl {

bool isSoftwareRendererName(std::string_view renderer)
{
    for (std::string_view name : {"llvmpipe", "softpipe", "swrast", "Software Rasterizer"})
        if (renderer.find(name) != std::string_view::npos)
            return true;
    return false;
}

bool isSoftwareRenderer()
{
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return renderer != nullptr && isSoftwareRendererName(renderer);
}

int queryInteger(unsigned name)
{
    GLint value = 0;
    glGetIntegerv(name, &value);
    return value;
}

}  // namespace manylights::gl
