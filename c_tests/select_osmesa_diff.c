/* ffl-test: osmesa-diff */
/*
 * Where OSMesa's selection differs from the spec (§5.2, §2.5); each case prints the
 * implementation's value and, after `ref`, the spec's:
 *  1. depth 1.0 (a primitive on or clipped at the far plane): the spec's
 *     round(1.0 * (2^32 - 1)) = 4294967295; OSMesa's float product 2^32 overflows
 *     the unsigned conversion and gives 0;
 *  2. polygons in GL_LINE or GL_POINT mode with every edge flag FALSE: "selection
 *     is based on the polygon itself, regardless of the setting of PolygonMode",
 *     a hit; OSMesa selects the edges or points drawn: no hit;
 *  3. glRenderMode with an unknown mode while selecting: no effect (§2.5); OSMesa
 *     ends the selection (writes the pending record, forgets the hit count) before
 *     it checks the mode. And glRenderMode(GL_SELECT) after glSelectBuffer(0, ...):
 *     the GL reference pages make it an error only before glSelectBuffer was ever
 *     called, as fflight does; OSMesa rejects an empty buffer too.
 */
#include "ffl_test.h"

static GLuint buf[512];

static void point(float z)
{
    glBegin(GL_POINTS);
    glVertex3f(0, 0, z);
    glEnd();
}

int main(void)
{
    GLint hits, mode;

    ffl_test_init();
    glViewport(0, 0, 64, 64);

    /* 1. Depth 1.0. */
    glSelectBuffer(512, buf);
    glRenderMode(GL_SELECT);
    glPushName(1);
    point(1.0f);
    glLoadName(2);
    glBegin(GL_LINES); /* clipped at the far plane */
    glVertex3f(0, 0, 0);
    glVertex3f(0, 0, 3);
    glEnd();
    hits = glRenderMode(GL_RENDER);
    printf("far hits %d ref hits 2\n", (int)hits);
    printf("far_point zhit %u %u ref zhit 4294967295 4294967295\n", buf[1], buf[2]);
    printf("far_line zhit %u %u ref zhit 2147483648 4294967295\n", buf[5], buf[6]);

    /* 2. Polygon mode with edge flags FALSE. */
    glSelectBuffer(512, buf);
    glRenderMode(GL_SELECT);
    glPushName(3);
    glEdgeFlag(GL_FALSE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glBegin(GL_TRIANGLES);
    glVertex3f(-0.5f, -0.5f, 0);
    glVertex3f(0.5f, -0.5f, 0);
    glVertex3f(0, 0.5f, 0);
    glEnd();
    glLoadName(4);
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    glBegin(GL_QUADS);
    glVertex3f(-0.5f, -0.5f, 0);
    glVertex3f(0.5f, -0.5f, 0);
    glVertex3f(0.5f, 0.5f, 0);
    glVertex3f(-0.5f, 0.5f, 0);
    glEnd();
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glEdgeFlag(GL_TRUE);
    hits = glRenderMode(GL_RENDER);
    printf("edge_flags hits %d ref hits 2\n", (int)hits);

    /* 3. glRenderMode in error. */
    glSelectBuffer(512, buf);
    glRenderMode(GL_SELECT);
    glPushName(5);
    point(0);
    glRenderMode(0x1234);
    printf("bad_mode error %d ref error %d\n", (int)glGetError(), GL_INVALID_ENUM);
    glGetIntegerv(GL_RENDER_MODE, &mode);
    printf("bad_mode mode %d ref mode %d\n", (int)mode, GL_SELECT);
    hits = glRenderMode(GL_RENDER);
    printf("bad_mode hits %d ref hits 1\n", (int)hits);

    glSelectBuffer(0, buf); /* given, empty: counts as given in the spec's words */
    glRenderMode(GL_SELECT);
    printf("size_0 error %d ref error %d\n", (int)glGetError(), GL_NO_ERROR);
    glRenderMode(GL_RENDER);
    return 0;
}
