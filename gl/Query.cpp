#include "gl/Query.h"

namespace manylights::gl {

namespace {
bool isPipelineStatistic(GLenum target)
{
    return target == GL_FRAGMENT_SHADER_INVOCATIONS_ARB || target == GL_VERTICES_SUBMITTED_ARB ||
           target == GL_PRIMITIVES_SUBMITTED_ARB || target == GL_VERTEX_SHADER_INVOCATIONS_ARB ||
           target == GL_CLIPPING_INPUT_PRIMITIVES_ARB || target == GL_CLIPPING_OUTPUT_PRIMITIVES_ARB ||
           target == GL_COMPUTE_SHADER_INVOCATIONS_ARB;
}

GLuint createQuery(GLenum target)
{
    GLuint name = 0;
    // Driver workaround: Mesa 22 (llvmpipe) rejects pipeline-statistics targets in
    // glCreateQueries with GL_INVALID_ENUM, though glBeginQuery accepts them. A name from
    // glGenQueries becomes a query of the right target at its first glBeginQuery.
    if (isPipelineStatistic(target))
        glGenQueries(1, &name);
    else
        glCreateQueries(target, 1, &name);
    return name;
}
}  // namespace

Query::Query(std::string_view label, GLenum target) : GlObject(createQuery(target)), target_(target)
{
    // A generated but never begun query is not an object yet and cannot be labelled.
    if (!isPipelineStatistic(target))
        setLabel(GL_QUERY, id(), label);
}

std::uint64_t Query::result() const
{
    GLuint64 value = 0;
    glGetQueryObjectui64v(id(), GL_QUERY_RESULT, &value);
    return value;
}

bool Query::available() const
{
    GLuint available = GL_FALSE;
    glGetQueryObjectuiv(id(), GL_QUERY_RESULT_AVAILABLE, &available);
    return available == GL_TRUE;
}

bool hasPipelineStatistics()
{
    return epoxy_gl_version() >= 46 || epoxy_has_gl_extension("GL_ARB_pipeline_statistics_query");
}

}  // namespace manylights::gl
