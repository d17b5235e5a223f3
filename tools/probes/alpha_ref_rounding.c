/* Probe for the fragment stages (run on Mesa: gcc tools/probes/alpha_ref_rounding.c -lOSMesa && ./a.out); see src/fragment/. */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>
int main(void){
  OSMesaContext c=OSMesaCreateContextExt(OSMESA_RGBA,0,0,0,NULL);
  static unsigned char buf[256*4*4];
  OSMesaMakeCurrent(c,buf,GL_UNSIGNED_BYTE,256,4);
  glViewport(0,0,256,4);glMatrixMode(GL_PROJECTION);glLoadIdentity();glOrtho(0,256,0,4,-1,1);
  for(int k=124;k<=129;k++){
    float ref=(k+0.5f)/255.0f;
    glClear(GL_COLOR_BUFFER_BIT);glEnable(GL_ALPHA_TEST);glAlphaFunc(GL_GEQUAL,ref);
    glBegin(GL_POINTS);for(int i=0;i<256;i++){glColor4f(1,1,1,i/255.0f);glVertex2f(i+0.5f,0.5f);}glEnd();
    glReadPixels(0,0,256,1,GL_RGBA,GL_UNSIGNED_BYTE,buf);
    int first=-1;for(int i=0;i<256;i++)if(buf[i*4]){first=i;break;}
    /* fragment tie: alpha (k+0.5)/255 against ref k/255 and (k+1)/255 */
    glAlphaFunc(GL_EQUAL,(float)k/255.0f);glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_POINTS);glColor4f(1,1,1,(k+0.5f)/255.0f);glVertex2f(0.5f,0.5f);glEnd();
    glReadPixels(0,0,1,1,GL_RGBA,GL_UNSIGNED_BYTE,buf);int eqk=buf[0]!=0;
    glAlphaFunc(GL_EQUAL,(float)(k+1)/255.0f);glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_POINTS);glColor4f(1,1,1,(k+0.5f)/255.0f);glVertex2f(0.5f,0.5f);glEnd();
    glReadPixels(0,0,1,1,GL_RGBA,GL_UNSIGNED_BYTE,buf);int eqk1=buf[0]!=0;
    printf("ref (%d+.5)/255 -> first passing alpha %d; alpha (%d+.5)/255 equals %d:%d %d:%d\n",k,first,k,k,eqk,k+1,eqk1);
  }
  return 0;}
