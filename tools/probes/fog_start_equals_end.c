/* Probe for the fragment stages (run on Mesa: gcc tools/probes/fog_start_equals_end.c -lOSMesa && ./a.out); see src/fragment/. */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>
int main(void){
  OSMesaContext c=OSMesaCreateContextExt(OSMESA_RGBA,0,0,0,NULL);
  static unsigned char buf[256*4*4];
  OSMesaMakeCurrent(c,buf,GL_UNSIGNED_BYTE,256,4);
  glViewport(0,0,256,4);glMatrixMode(GL_PROJECTION);glLoadIdentity();glOrtho(0,256,0,4,-10,10);
  glEnable(GL_FOG);glFogfv(GL_FOG_COLOR,(float[]){0,0,1,1});glFogi(GL_FOG_MODE,GL_LINEAR);
  float se[]={0.3f,0.0f,-0.2f,2.0f};
  for(int k=0;k<4;k++){
    glFogf(GL_FOG_START,se[k]);glFogf(GL_FOG_END,se[k]);glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_POINTS);for(int i=0;i<16;i++){glColor4f(1,0,0,1);glVertex3f(i+0.5f,0.5f,-(i*0.1f)+0.3f);}glEnd();
    glReadPixels(0,0,16,1,GL_RGBA,GL_UNSIGNED_BYTE,buf);
    printf("start=end=%g (eye z from 0.3 down by 0.1):",se[k]);for(int i=0;i<16;i++)printf(" %d/%d",buf[i*4],buf[i*4+2]);printf("\n");
  }
  /* fog coordinate source, start==end */
  glFogi(GL_FOG_COORDINATE_SOURCE,GL_FOG_COORDINATE);glFogf(GL_FOG_START,0.5f);glFogf(GL_FOG_END,0.5f);
  void (*fc)(float)=(void(*)(float))OSMesaGetProcAddress("glFogCoordf");
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_POINTS);for(int i=0;i<16;i++){glColor4f(1,0,0,1);fc(i*0.1f-0.3f);glVertex3f(i+0.5f,0.5f,0);}glEnd();
  glReadPixels(0,0,16,1,GL_RGBA,GL_UNSIGNED_BYTE,buf);
  printf("fogcoord -0.3..1.2 start=end=0.5:");for(int i=0;i<16;i++)printf(" %d/%d",buf[i*4],buf[i*4+2]);printf("\n");
  return 0;}
