/* A freeglut program drawing with the fragment operations tessera has (no lighting, no
 * texturing): a smooth-shaded triangle over a blue background, a green quad hiding a magenta
 * one by the depth test, a half-transparent yellow rectangle blended over the background, and
 * a stippled line. tools/xvfb-tests.sh runs it on tessera
 * under Xvfb and checks a screenshot of its window.
 *
 * (Not in examples-c/: tools/main-job.sh builds those as OSMesa programs.)
 * Build: gcc tests/glx/glut_scene.c -lglut -lGL -o glut_scene
 * Run:   LD_LIBRARY_PATH=target/release ./glut_scene [--frames N]
 * After the first frame it prints "frame shown" (the screenshot may be taken); it exits after
 * N frames (default: runs until the window is closed). */
#include <GL/glut.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int frames_left = -1;
static int frames_shown = 0;

static void display(void)
{
    glClearColor(0.0f, 0.0f, 0.6f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);

    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex3f(-0.9f, -0.9f, 0.5f);
    glColor3f(0, 1, 0); glVertex3f(-0.1f, -0.9f, 0.5f);
    glColor3f(1, 1, 1); glVertex3f(-0.5f, -0.1f, 0.5f);
    glEnd();

    glColor3f(0, 1, 0);
    glRectf(0.1f, 0.1f, 0.9f, 0.9f);              /* z = 0: in front */
    glColor3f(1, 0, 1);
    glBegin(GL_QUADS);                             /* behind the green one: hidden */
    glVertex3f(0.2f, 0.2f, 0.8f); glVertex3f(0.8f, 0.2f, 0.8f);
    glVertex3f(0.8f, 0.8f, 0.8f); glVertex3f(0.2f, 0.8f, 0.8f);
    glEnd();

    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColor4f(1, 1, 0, 0.5f);
    glRectf(0.5f, -0.9f, 0.9f, -0.1f);             /* half yellow over blue */
    glDisable(GL_BLEND);

    glEnable(GL_LINE_STIPPLE);
    glLineStipple(2, 0x0f0f);
    glColor3f(1, 1, 1);
    glBegin(GL_LINES);
    glVertex2f(-0.9f, 0.5f); glVertex2f(-0.1f, 0.5f);
    glEnd();
    glDisable(GL_LINE_STIPPLE);

    glutSwapBuffers();
    if (frames_shown++ == 0) {
        printf("frame shown\n");
        fflush(stdout);
    }
    if (frames_left > 0 && --frames_left == 0)
        exit(0);
}

static void reshape(int w, int h)
{
    glViewport(0, 0, w, h);
}

static void timer(int value)
{
    (void)value;
    glutPostRedisplay();
    glutTimerFunc(50, timer, 0);
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    for (int i = 1; i + 1 < argc; i++)
        if (strcmp(argv[i], "--frames") == 0)
            frames_left = atoi(argv[i + 1]);
    glutInitDisplayMode(GLUT_RGBA | GLUT_DOUBLE | GLUT_DEPTH);
    glutInitWindowPosition(0, 0);
    glutInitWindowSize(300, 300);
    glutCreateWindow("tessera glut_scene");
    printf("GL_RENDERER = %s\n", (const char *)glGetString(GL_RENDERER));
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutTimerFunc(50, timer, 0);
    glutMainLoop();
    return 0;
}
