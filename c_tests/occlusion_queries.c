/* ffl-test: differential */
/*
 * Occlusion queries (GL 1.5 §4.1.7, §6.1.12): names, glBeginQuery /
 * glEndQuery, GL_CURRENT_QUERY, results and availability, deletion of the
 * active query, and every error in Mesa's order. Nothing is rasterized
 * within the queries (feedback mode), so the result is 0 in both builds.
 * GL_QUERY_COUNTER_BITS differs by design: fflight has no rasterizer and
 * reports 0 bits, which §6.1.12 allows; it is checked in the fflight build
 * only (the line is printed by both, compared as text: "bits_zero yes/no").
 */
#include "ffl_test.h"

static void error(const char *what)
{
    printf("%s error %s\n", what, ffl_error_name(glGetError()));
}

int main(void)
{
    GLuint ids[3], more[2], available = 7;
    GLint value = -7;
    GLfloat feedback[64];

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glGenQueries(-1, ids);
    error("gen_negative");
    glGenQueries(0, NULL);
    error("gen_none");
    glGenQueries(3, ids);
    printf("names %u %u %u is %d", ids[0], ids[1], ids[2], (int)glIsQuery(ids[0]));
    error("");
    glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &value);
    printf("current %d", value);
    error("");
    glGetQueryiv(GL_SAMPLES_PASSED, GL_QUERY_COUNTER_BITS, &value);
#ifdef FFL_OSMESA
    printf("bits_zero yes");
#else
    printf("bits_zero %s", value == 0 ? "yes" : "no");
#endif
    error("");
    glGetQueryiv(0x1234, GL_CURRENT_QUERY, &value);
    error("get_bad_target");
    glGetQueryiv(GL_SAMPLES_PASSED, 0x1234, &value);
    error("get_bad_pname");
    glBeginQuery(0x1234, ids[0]);
    error("begin_bad_target");
    glBeginQuery(GL_SAMPLES_PASSED, 0);
    error("begin_zero");

    glFeedbackBuffer(64, GL_3D, feedback);
    glRenderMode(GL_FEEDBACK);
    glBeginQuery(GL_SAMPLES_PASSED, ids[0]);
    printf("began is %d", (int)glIsQuery(ids[0]));
    error("");
    glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &value);
    printf("current %d", value);
    error("");
    glBegin(GL_TRIANGLES);
    glVertex3f(0, 0, 0);
    glVertex3f(0.5f, 0, 0);
    glVertex3f(0, 0.5f, 0);
    glEnd();
    glBeginQuery(GL_SAMPLES_PASSED, ids[1]);
    error("begin_while_active");
    glGetQueryObjectiv(ids[0], GL_QUERY_RESULT, &value);
    error("result_while_active");
    glEndQuery(0x1234);
    error("end_bad_target");
    glEndQuery(GL_SAMPLES_PASSED);
    error("end");
    glEndQuery(GL_SAMPLES_PASSED);
    error("end_again");
    glRenderMode(GL_RENDER);
    value = -7;
    glGetQueryObjectiv(ids[0], GL_QUERY_RESULT, &value);
    printf("result %d", value);
    error("");
    glGetQueryObjectuiv(ids[0], GL_QUERY_RESULT_AVAILABLE, &available);
    printf("available %u", available);
    error("");
    glGetQueryObjectiv(ids[0], 0x1234, &value);
    error("object_bad_pname");
    glGetQueryObjectiv(ids[1], GL_QUERY_RESULT, &value);
    error("object_never_begun");
    glGetQueryObjectiv(99, GL_QUERY_RESULT, &value);
    error("object_unknown");

    glBeginQuery(GL_SAMPLES_PASSED, 50);
    printf("unused_name is %d", (int)glIsQuery(50));
    error("");
    glEndQuery(GL_SAMPLES_PASSED);
    glDeleteQueries(-1, ids);
    error("delete_negative");
    glBeginQuery(GL_SAMPLES_PASSED, ids[0]);
    glDeleteQueries(1, ids);
    glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &value);
    printf("deleted_active current %d is %d", value, (int)glIsQuery(ids[0]));
    error("");
    glEndQuery(GL_SAMPLES_PASSED);
    error("end_after_delete");
    glBegin(GL_POINTS);
    glBeginQuery(GL_SAMPLES_PASSED, ids[2]);
    glEnd();
    error("begin_inside_begin_end");
    glGenQueries(2, more);
    printf("more %u %u", more[0], more[1]);
    error("");
    return 0;
}
