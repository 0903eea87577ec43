/* ffl-test: fflight-only */
/* The example of README.md's "Capture API" section, kept compiling here. */
#include "fflight.h"
#include <stdio.h>
#include <string.h>

int main(void)
{
    static const GLfloat light[4] = { 0, 0, 1, 0 };
    static const GLfloat positions[3][3] = { { 0, 0, -2 }, { 1, 0, -2 }, { 0, 1, -2 } };
    static const GLfloat normals[3][3] = { { 0, 0, 1 }, { 0, 0, 1 }, { 0.6f, 0, 0.8f } };
    GLfloat colors[3][4];
    FflCapturedPrimitive triangle;
    FflCapturedVertex corners[3];
    GLuint k;
    int same = 1;

    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, light);

    /* 1. Light an array: only the front primary colors, tightly packed. */
    fflLightVertices(3, 3, &positions[0][0], 0, &normals[0][0], 0, NULL, 0,
                     NULL, 0, NULL, 0, &colors[0][0], 0, NULL, 0, NULL, 0, NULL, 0);

    /* 2. Capture what a draw makes of the same vertices. */
    glVertexPointer(3, GL_FLOAT, 0, positions);
    glNormalPointer(GL_FLOAT, 0, normals);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    fflCaptureBegin();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    fflCaptureEnd();

    fflCaptureReadPrimitives(0, 1, &triangle);
    fflCaptureReadVertices(0, 3, corners);
    for (k = 0; k < triangle.vertex_count; k++) {
        const FflCapturedVertex *v = &corners[triangle.vertices[k]];
        printf("clip %g %g %g %g  color %g %g %g %g\n", v->clip[0], v->clip[1], v->clip[2],
               v->clip[3], v->front_primary[0], v->front_primary[1], v->front_primary[2],
               v->front_primary[3]);
        /* The bulk call and the draw light the same vertex the same way. */
        same &= memcmp(v->front_primary, colors[triangle.vertices[k]], sizeof colors[0]) == 0;
    }
    return !same || glGetError() != GL_NO_ERROR;
}
