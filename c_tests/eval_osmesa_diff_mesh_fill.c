/* ffl-test: osmesa-diff */
/*
 * Two places where OSMesa's evaluators depart from §5.1:
 * - glEvalMesh2(GL_FILL, ...) is the spec's code fragment: for each grid row a
 *   GL_QUAD_STRIP of glEvalCoord2 pairs. OSMesa draws triangle strips instead, so its
 *   feedback holds other triangles (the other diagonal of each quad). Checked here by
 *   comparing the mesh's feedback, value for value, with the fragment drawn by hand.
 * - "Use of evaluators has no effect on the current color, normal, or texture
 *   coordinates": after glEvalCoord2 with normal and texture coordinate maps enabled (in
 *   feedback mode), the current normal and texture coordinates are those set before.
 *   OSMesa leaves other values there (the current color in the normal).
 */
#include "ffl_test.h"

#define BUF_SIZE 4096

static GLfloat mesh[BUF_SIZE], by_hand[BUF_SIZE];

int main(void)
{
    static const GLfloat normals[2][2][3] = {
        { { 0, 0, 1 }, { 0, 1, 1 } }, { { 1, 0, 1 }, { 1, 1, 0 } },
    };
    static const GLfloat tex[2][2][2] = { { { 0, 0 }, { 0, 1 } }, { { 1, 0 }, { 1, 1 } } };
    GLfloat patch[3][3][3];
    GLint n_mesh, n_hand, i, j;
    int same;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-4, 4, -4, 4, -10, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(30.0f, 1.0f, 0.2f, 0.0f);
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            patch[i][j][0] = -2.0f + 2.0f * (float)i;
            patch[i][j][1] = -2.0f + 2.0f * (float)j + 0.25f * (float)(i * i);
            patch[i][j][2] = i == 1 && j == 1 ? 2.0f : 0.0f;
        }
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_AUTO_NORMAL);
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 3, 0, 1, 9, 3, &patch[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glMapGrid2f(3, 0.0f, 1.0f, 2, 0.0f, 1.0f);

    glFeedbackBuffer(BUF_SIZE, GL_3D_COLOR, mesh);
    glRenderMode(GL_FEEDBACK);
    glEvalMesh2(GL_FILL, 0, 3, 0, 2);
    n_mesh = glRenderMode(GL_RENDER);
    glFeedbackBuffer(BUF_SIZE, GL_3D_COLOR, by_hand);
    glRenderMode(GL_FEEDBACK);
    for (j = 0; j < 2; j++) {
        glBegin(GL_QUAD_STRIP);
        for (i = 0; i <= 3; i++) {
            glEvalPoint2(i, j);
            glEvalPoint2(i, j + 1);
        }
        glEnd();
    }
    n_hand = glRenderMode(GL_RENDER);
    same = n_mesh == n_hand && n_mesh > 0 &&
           memcmp(mesh, by_hand, (size_t)n_mesh * sizeof mesh[0]) == 0;
    printf("mesh_fill count %d\n", (int)n_mesh);
    ffl_print_feedback("mesh_fill", mesh, n_mesh, GL_3D_COLOR);
    printf("fill_is_the_quad_strip_fragment same %d ref same 1\n", same);

    glDisable(GL_AUTO_NORMAL);
    glMap2f(GL_MAP2_NORMAL, 0, 1, 6, 2, 0, 1, 3, 2, &normals[0][0][0]);
    glMap2f(GL_MAP2_TEXTURE_COORD_2, 0, 1, 4, 2, 0, 1, 2, 2, &tex[0][0][0]);
    glEnable(GL_MAP2_NORMAL);
    glEnable(GL_MAP2_TEXTURE_COORD_2);
    glColor4f(0.2f, 0.4f, 0.6f, 0.8f);
    glNormal3f(0.0f, 0.0f, -1.0f);
    glTexCoord4f(0.1f, 0.2f, 0.3f, 0.4f);
    /* In feedback mode, as a program reading its evaluated geometry back would. */
    glFeedbackBuffer(BUF_SIZE, GL_3D_COLOR, mesh);
    glRenderMode(GL_FEEDBACK);
    glBegin(GL_TRIANGLES);
    glEvalCoord2f(0.0f, 0.0f);
    glEvalCoord2f(1.0f, 0.25f);
    glEvalCoord2f(0.5f, 1.0f);
    glEnd();
    glRenderMode(GL_RENDER);
    {
        GLfloat v[4];
        glGetFloatv(GL_CURRENT_NORMAL, v);
        printf("current_normal");
        ffl_pfv("n", v, 3);
        printf(" ref n 0 0 -1\n");
        glGetFloatv(GL_CURRENT_TEXTURE_COORDS, v);
        printf("current_texcoord");
        ffl_pfv("strq", v, 4);
        printf(" ref strq 0.1 0.2 0.3 0.4\n");
    }
    ffl_print_error("eval");
    return 0;
}
