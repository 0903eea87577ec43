/* ffl-test: differential */
/*
 * The current raster position (§2.13): glRasterPos processes its position
 * like a vertex (modelview, projection, lighting with the current normal,
 * color and material, the texture coordinate through the texture matrix),
 * clips it as a point against the view volume and the enabled user clip
 * planes, and keeps window x, y, z, the clip w, the front primary and
 * secondary colors, the texture coordinate and the eye distance. A culled
 * position makes GL_CURRENT_RASTER_POSITION_VALID false and leaves the rest
 * unchanged. Positions and directional lights go through a rotated and
 * translated modelview; point and spot lights and the local viewer through
 * the identity (see osmesa_diff_raster_pos_lighting.c). Each lit position
 * is also drawn as a point in feedback: its fed-back color is printed next
 * to the raster color. Then the initial state, integer queries,
 * glRasterPos between glBegin and glEnd, feedback mode (no token) and
 * selection mode (a hit).
 */
#include "ffl_test.h"

static void print_raster(const char *what)
{
    GLfloat position[4], color[4], secondary[4], tex[4], distance;
    GLboolean valid;
    glGetFloatv(GL_CURRENT_RASTER_POSITION, position);
    glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
    glGetFloatv(GL_CURRENT_RASTER_COLOR, color);
    glGetFloatv(GL_CURRENT_RASTER_SECONDARY_COLOR, secondary);
    glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, tex);
    glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &distance);
    printf("%s valid %d", what, valid ? 1 : 0);
    ffl_pfv("xyzw", position, 4);
    ffl_pfv("rgba", color, 4);
    ffl_pfv("secondary_rgb", secondary, 3);
    ffl_pfv("strq", tex, 4);
    ffl_pfv("distance", &distance, 1);
    printf("\n");
}

/* The color a point at the same position gets in feedback (nothing if culled). */
static void print_feedback_point(const char *what, const GLfloat *p)
{
    GLfloat buf[16];
    GLint n;
    glFeedbackBuffer(16, GL_3D_COLOR, buf);
    glRenderMode(GL_FEEDBACK);
    glBegin(GL_POINTS);
    glVertex4fv(p);
    glEnd();
    n = glRenderMode(GL_RENDER);
    printf("%s feedback %d", what, (int)n);
    if (n == 8)
        ffl_pfv("rgba", buf + 4, 4);
    printf("\n");
}

static const GLfloat positions[][4] = {
    { 0, 0, -5, 1 },       { 1.5f, -0.5f, -3, 1 },  { -2, 0.6f, -8, 1 },
    { 0.5f, 0.5f, -2, 1 }, { 0, 0, -0.5f, 1 },      /* nearer than the near plane */
    { 30, 0, -5, 1 },      /* right of the view */  { 0, 0, -50, 1 }, /* beyond far */
    { 0, 0, 5, 1 },        /* behind the eye */     { -1, -1, -4, 1 },
    { 0.3f, 1.2f, -6, 1 }, /* cut by the user plane y <= 1 */
};
#define NUM_POSITIONS ((int)(sizeof positions / sizeof positions[0]))

static void run_positions(const char *state)
{
    char what[96];
    int i;
    for (i = 0; i < NUM_POSITIONS; i++) {
        glNormal3f(0.2f * (float)i - 0.5f, 0.3f, 0.8f);
        glColor4f(0.9f, 0.5f - 0.04f * (float)i, 0.3f, 0.75f);
        glTexCoord4f(0.1f * (float)i, 0.5f, -0.25f, 1);
        glRasterPos4fv(positions[i]);
        snprintf(what, sizeof what, "%s p%d", state, i);
        print_raster(what);
        print_feedback_point(what, positions[i]);
    }
}

int main(void)
{
    static const GLfloat directional[4] = { 0.3f, 0.5f, 1, 0 };
    static const GLfloat point[4] = { -1, 2, 1, 1 };
    static const GLfloat spot_dir[3] = { 0.2f, -0.5f, -1 };
    static const GLfloat red[4] = { 0.9f, 0.2f, 0.1f, 1 };
    static const GLfloat spec[4] = { 0.8f, 0.8f, 0.6f, 1 };
    static const GLfloat amb[4] = { 0.2f, 0.1f, 0.3f, 1 };
    static const GLfloat mat_diffuse[4] = { 0.4f, 0.7f, 0.5f, 0.6f };
    static const GLdouble plane[4] = { 0, -1, 0, 1 }; /* y <= 1 */
    GLint ints[4];
    GLfloat floats[4];
    GLfloat fb[8];
    GLuint select[16];
    GLint n;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    print_raster("initial");
    glGetIntegerv(GL_CURRENT_RASTER_COLOR, ints);
    printf("initial int color %d %d %d %d\n", ints[0], ints[1], ints[2], ints[3]);
    glGetIntegerv(GL_CURRENT_RASTER_POSITION, ints);
    printf("initial int position %d %d %d %d\n", ints[0], ints[1], ints[2], ints[3]);

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1, 1, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.1f, -0.2f, 0);
    glRotatef(10, 0, 1, 0);

    run_positions("unlit");

    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, directional);
    glLightfv(GL_LIGHT0, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
    run_positions("light0");

    /* OSMesa lights a raster position at its object coordinates when lighting needs the
     * vertex position (a point light, a local viewer): so from here the modelview is the
     * identity (osmesa_diff_raster_pos_lighting.c shows the difference). */
    glLoadIdentity();
    glEnable(GL_LIGHT1);
    glLightfv(GL_LIGHT1, GL_POSITION, point);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, red);
    glLightfv(GL_LIGHT1, GL_AMBIENT, amb);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.2f);
    glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, spot_dir);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 60);
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 3);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, mat_diffuse);
    run_positions("point_spot_local");

    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    run_positions("separate_specular");
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);

    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    run_positions("two_side_color_material");
    glDisable(GL_COLOR_MATERIAL);

    glClipPlane(GL_CLIP_PLANE0, plane);
    glEnable(GL_CLIP_PLANE0);
    run_positions("clip_plane");

    /* A culled position leaves the rest of the raster state alone. */
    glRasterPos3f(0, 0, -5);
    print_raster("before_cull");
    glColor3f(0, 1, 0);
    glTexCoord2f(0.75f, 0.25f);
    glRasterPos3f(0, 3, -5);
    print_raster("after_cull");
    glDisable(GL_CLIP_PLANE0);
    glDisable(GL_LIGHTING);

    /* The texture matrix. */
    glMatrixMode(GL_TEXTURE);
    glTranslatef(0.25f, -0.5f, 0.125f);
    glRotatef(30, 0, 0, 1);
    glScalef(2, 0.5f, 1.5f);
    glMatrixMode(GL_MODELVIEW);
    glTexCoord4f(0.6f, 0.1f, 0.3f, 0.5f);
    glRasterPos3f(0.5f, -0.25f, -5);
    print_raster("texture_matrix");
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);

    /* Integer forms of the queries. */
    glColor4f(0.25f, 0.5f, 0.75f, 1);
    glRasterPos3f(0.4f, 0.3f, -4);
    glGetIntegerv(GL_CURRENT_RASTER_COLOR, ints);
    printf("int color %d %d %d %d\n", ints[0], ints[1], ints[2], ints[3]);
    glGetIntegerv(GL_CURRENT_RASTER_POSITION, ints);
    printf("int position %d %d %d %d\n", ints[0], ints[1], ints[2], ints[3]);
    glGetFloatv(GL_CURRENT_RASTER_POSITION, floats);
    printf("float position");
    ffl_pfv("xyzw", floats, 4);
    printf("\n");

    /* Between glBegin and glEnd. */
    glBegin(GL_POINTS);
    glRasterPos2f(0, 0);
    glEnd();
    ffl_print_error("raster_pos_in_begin_end");
    print_raster("after_error");

    /* Feedback mode: glRasterPos adds no token. */
    glFeedbackBuffer(8, GL_3D_COLOR, fb);
    glRenderMode(GL_FEEDBACK);
    glRasterPos3f(0, 0, -5);
    glPassThrough(7);
    n = glRenderMode(GL_RENDER);
    printf("feedback count %d", (int)n);
    ffl_pfv("values", fb, n < 8 ? (int)n : 8);
    printf("\n");

    /* Selection mode: a valid position is a hit, a culled one is not. */
    glSelectBuffer(16, select);
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(1);
    glRasterPos3f(0, 0, -5);
    glLoadName(2);
    glRasterPos3f(0, 0, 5);
    glLoadName(3);
    n = glRenderMode(GL_RENDER);
    printf("select hits %d", (int)n);
    if (n >= 1)
        printf(" names %u zhit %u %u name %u", select[0], select[1], select[2], select[3]);
    printf("\n");
    ffl_print_error("end");
    return 0;
}
