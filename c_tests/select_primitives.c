/* ffl-test: differential */
/*
 * Selection (§5.2) of every glBegin mode under a perspective projection: points,
 * segments, triangles, quads and polygons inside, crossing the near plane and the
 * sides of the view volume (clipped: the record holds the clipped depths), entirely
 * outside (no hit), back faces culled, polygons in GL_LINE and GL_POINT mode (edge
 * flags all TRUE: the spec and OSMesa agree there), nested names with hits at every
 * level. Nothing crosses the far plane: OSMesa records depth 1.0 as 0, and a
 * depth a rounding below 0 as about 2^32 (see select_osmesa_diff.c). Prints every
 * hit record.
 */
#include "ffl_test.h"

static void shape(GLenum mode, const float (*v)[3], int n)
{
    int k;
    glBegin(mode);
    for (k = 0; k < n; k++)
        glVertex3fv(v[k]);
    glEnd();
}

int main(void)
{
    static GLuint buf[1024];
    static const float points[4][3] = {
        { 0, 0, -3 }, { 0.5f, 0.2f, -5 }, { 9, 0, -3 }, { -0.3f, -0.4f, -1.5f } };
    static const float lines[6][3] = {
        { -0.5f, 0, -2 }, { 0.5f, 0.1f, -6 },      /* inside */
        { 0, 0, -0.5f }, { 0.2f, 0.3f, -4 },       /* crosses the near plane */
        { -8, 0, -3 }, { 8, 0.5f, -3.5f } };       /* crosses both sides */
    static const float strip[4][3] = {
        { -3, -1, -4 }, { -1, 1, -3 }, { 1, -1, -5 }, { 3, 1, -2 } };
    static const float far_away[3][3] = { { 5, 5, -3 }, { 6, 5, -3 }, { 5, 6, -3 } };
    static const float triangles[6][3] = {
        { -0.5f, -0.5f, -2 }, { 0.5f, -0.5f, -3 }, { 0, 0.5f, -4 },       /* CCW */
        { -0.5f, -0.5f, -0.2f }, { 0.6f, -0.3f, -3 }, { 0, 0.7f, -5 } };  /* near plane */
    static const float back[3][3] = { { -0.5f, -0.5f, -2 }, { 0, 0.5f, -4 }, { 0.5f, -0.5f, -3 } };
    static const float quads[8][3] = {
        { -3, -3, -4 }, { 3, -3, -5 }, { 3, 3, -6 }, { -3, 3, -5 },     /* covers the view */
        { 0.1f, 0.1f, -2 }, { 0.6f, 0.1f, -2.5f }, { 0.6f, 0.6f, -3 }, { 0.1f, 0.6f, -2.5f } };
    static const float fan[5][3] = {
        { 0, 0, -3 }, { 1, 0, -2 }, { 0, 1, -2.5f }, { -1, 0, -0.8f }, { 0, -1, -6 } };
    static const float polygon[5][3] = {
        { -1, -1, -2 }, { 1, -1.2f, -3 }, { 1.3f, 0.5f, -4 }, { 0, 1.5f, -5 }, { -1.2f, 0.4f, -2.5f } };
    static const float quad_strip[6][3] = {
        { -2, -0.5f, -3 }, { -2, 0.5f, -3 }, { 0, -0.5f, -1.5f }, { 0, 0.5f, -1.5f },
        { 2, -0.5f, -7 }, { 2, 0.5f, -7 } };
    GLint hits;
    int bad;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1, 1, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(10, 0.3f, 1, 0.2f);

    glSelectBuffer(1024, buf);
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(1);
    shape(GL_POINTS, points, 4);
    glLoadName(2);
    shape(GL_LINES, lines, 2);
    glLoadName(3);
    shape(GL_LINES, lines + 2, 2);
    glLoadName(4);
    shape(GL_LINES, lines + 4, 2);
    glLoadName(5);
    shape(GL_LINE_STRIP, strip, 4);
    glLoadName(6);
    shape(GL_LINE_LOOP, strip, 4);
    glLoadName(7);
    shape(GL_TRIANGLES, far_away, 3); /* no hit: no record for 7 */
    glLoadName(8);
    shape(GL_TRIANGLES, triangles, 3);
    glPushName(80);
    shape(GL_TRIANGLES, triangles + 3, 3);
    glPushName(800);
    shape(GL_QUADS, quads, 8);
    glPopName();
    glLoadName(81);
    shape(GL_TRIANGLE_FAN, fan, 5);
    glPopName();
    glLoadName(9);
    shape(GL_POLYGON, polygon, 5);
    glLoadName(10);
    shape(GL_QUAD_STRIP, quad_strip, 6);
    glLoadName(11);
    shape(GL_TRIANGLE_STRIP, quad_strip, 6);

    /* Culling: the back face makes no hit, the front face does. */
    glEnable(GL_CULL_FACE);
    glLoadName(12);
    shape(GL_TRIANGLES, back, 3);
    glLoadName(13);
    shape(GL_TRIANGLES, triangles, 3);
    glCullFace(GL_FRONT);
    glLoadName(14);
    shape(GL_TRIANGLES, triangles, 3);
    glLoadName(15);
    shape(GL_TRIANGLES, back, 3);
    glDisable(GL_CULL_FACE);

    /* Polygon modes, edge flags TRUE: the same hits as GL_FILL. */
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glLoadName(16);
    shape(GL_POLYGON, polygon, 5);
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    glLoadName(17);
    shape(GL_QUADS, quads, 8);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);

    /* Nested names, a hit at every depth, then glInitNames. */
    glLoadName(18);
    {
        GLuint level;
        for (level = 0; level < 6; level++) {
            glPushName(100 + level);
            shape(GL_POINTS, points + (level % 4), 1);
        }
    }
    glInitNames();
    shape(GL_POINTS, points, 1); /* a hit with an empty name stack */
    hits = glRenderMode(GL_RENDER);
    bad = ffl_print_hits("select", buf, hits, 1024);
    ffl_print_error("after");
    return bad;
}
