/* ffl-test: osmesa-diff */
/*
 * OSMesa vs the spec: the lighting of the raster position (§2.13). The
 * raster position is lit exactly like a vertex, at its eye-space position.
 * OSMesa's glRasterPos (Mesa's _mesa_RasterPos, software) lights it at its
 * object coordinates whenever lighting needs the position (a point or spot
 * light, a local viewer) and the modelview is not the identity: a
 * translated modelview changes nothing. Its feedback path lights the same
 * vertex right. A point light with attenuation and a directional light with
 * a local viewer, under a translated and rotated modelview; each raster
 * color carries the spec's lit color as its reference, and the fed-back
 * color of the same vertex is printed too.
 */
#include "ffl_test.h"
#include "reference/gl_mirror.h"

static void raster_and_feedback(ref_state *ref, const char *what, const float *p)
{
    GLfloat color[4], buf[16];
    double obj[4], expect[4], secondary[4];
    GLint n;
    int c;
    for (c = 0; c < 4; c++)
        obj[c] = p[c];
    ref_lit_color(ref, obj, 0, expect, secondary);
    glRasterPos4fv(p);
    glGetFloatv(GL_CURRENT_RASTER_COLOR, color);
    printf("%s raster", what);
    ffl_pfv("rgba", color, 4);
    printf(" ref");
    ffl_pdv("rgba", expect, 4);
    printf("\n");
    glFeedbackBuffer(16, GL_3D_COLOR, buf);
    glRenderMode(GL_FEEDBACK);
    glBegin(GL_POINTS);
    glVertex4fv(p);
    glEnd();
    n = glRenderMode(GL_RENDER);
    printf("%s feedback %d", what, (int)n);
    if (n == 8) {
        ffl_pfv("rgba", buf + 4, 4);
        printf(" ref");
        ffl_pdv("rgba", expect, 4);
    }
    printf("\n");
}

int main(void)
{
    static const float p[4] = { 0.5f, 0.2f, -3, 1 };
    ref_state ref;

    ffl_test_init();
    ref_init(&ref);
    mirror_standard_view(&ref);
    mirror_translatef(&ref, 0.1f, -0.2f, -1);
    mirror_rotatef(&ref, 10, 0, 1, 0);
    mirror_light4f(&ref, GL_LIGHT0, GL_POSITION, -1, 2, 1, 1);
    mirror_light4f(&ref, GL_LIGHT0, GL_SPECULAR, 0.8f, 0.8f, 0.6f, 1);
    mirror_lightf(&ref, GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.2f);
    mirror_material4f(&ref, GL_FRONT, GL_SPECULAR, 0.8f, 0.8f, 0.6f, 1);
    mirror_materialf(&ref, GL_FRONT, GL_SHININESS, 20);
    mirror_enable(&ref, GL_LIGHT0, 1);
    mirror_enable(&ref, GL_LIGHTING, 1);
    mirror_normal3f(&ref, 0.3f, 0.4f, 0.8f);
    mirror_color4f(&ref, 0.9f, 0.5f, 0.3f, 0.75f);
    printf("stored_state");
    mirror_print_deviation(mirror_read_stored_state(&ref));
    printf("\n");
    raster_and_feedback(&ref, "point_light", p);

    mirror_light4f(&ref, GL_LIGHT0, GL_POSITION, 0.3f, 0.5f, 1, 0);
    mirror_light_modeli(&ref, GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    raster_and_feedback(&ref, "local_viewer", p);
    ffl_print_error("end");
    return 0;
}
