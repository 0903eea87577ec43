/*
 * What the feedback examples under examples/legacy/ share, written against the system
 * <GL/gl.h> only: a 64 x 64 OSMesa context when built with -DFFL_OSMESA (nothing against
 * fflight, which needs no setup call), and a printer of the feedback buffer.
 */
#ifndef LEGACY_FEEDBACK_H
#define LEGACY_FEEDBACK_H

#include <GL/gl.h>
#include <stdio.h>
#ifdef FFL_OSMESA
#include <GL/osmesa.h>
#endif

/* Makes a context current where the GL needs one. Returns 0 on success. */
static int legacy_make_current(void)
{
#ifdef FFL_OSMESA
    static GLubyte color_buffer[64 * 64 * 4];
    OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    if (context == NULL || !OSMesaMakeCurrent(context, color_buffer, GL_UNSIGNED_BYTE, 64, 64))
        return 1;
#endif
    return 0;
}

/* Prints a GL_3D_COLOR or GL_3D_COLOR_TEXTURE feedback buffer of n values: one line per
 * polygon, segment (whatever its token) or point, then one line per vertex with its window
 * position, color and (GL_3D_COLOR_TEXTURE) texture coordinates. */
static void legacy_print_feedback(const char *tag, const GLfloat *buf, GLint n, GLenum type)
{
    int size = type == GL_3D_COLOR_TEXTURE ? 11 : 7, k, count;
    GLint i = 0;
    printf("%s count %d\n", tag, (int)n);
    while (i < n) {
        GLint token = (GLint)buf[i++];
        const char *name = "polygon";
        if (token == GL_POLYGON_TOKEN && i < n) {
            count = (int)buf[i++];
        } else if (token == GL_LINE_TOKEN || token == GL_LINE_RESET_TOKEN) {
            name = "segment";
            count = 2;
        } else if (token == GL_POINT_TOKEN) {
            name = "point";
            count = 1;
        } else {
            printf("%s unexpected token %d\n", tag, (int)token);
            return;
        }
        printf("%s %s %d\n", tag, name, count);
        for (k = 0; k < count && i + size <= n; k++, i += size) {
            const GLfloat *v = buf + i;
            printf("%s  v xyz %.9g %.9g %.9g rgba %.9g %.9g %.9g %.9g", tag, v[0], v[1], v[2],
                   v[3], v[4], v[5], v[6]);
            if (size == 11)
                printf(" strq %.9g %.9g %.9g %.9g", v[7], v[8], v[9], v[10]);
            printf("\n");
        }
    }
}

#endif /* LEGACY_FEEDBACK_H */
