/* Probe for the fragment stages (run on Mesa: gcc tools/probes/stencil_ops.c -lOSMesa && ./a.out); see src/fragment/. */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>
static const GLenum OPS[8]={GL_KEEP,GL_ZERO,GL_REPLACE,GL_INCR,GL_DECR,0x8507,0x8508,GL_INVERT};
static unsigned op(int o,unsigned ref,unsigned v){switch(o){case 0:return v;case 1:return 0;case 2:return ref;case 3:return v<255?v+1:255;case 4:return v?v-1:0;case 5:return (v+1)&255;case 6:return (v-1)&255;default:return (~v)&255;}}
int main(void){
  OSMesaContext c=OSMesaCreateContextExt(OSMESA_RGBA,24,8,0,NULL);
  static unsigned char buf[256*4*4]; unsigned char st[256];
  OSMesaMakeCurrent(c,buf,GL_UNSIGNED_BYTE,256,4);
  glViewport(0,0,256,4);glMatrixMode(GL_PROJECTION);glLoadIdentity();glOrtho(0,256,0,4,-1,1);
  glEnable(GL_STENCIL_TEST);glEnable(GL_DEPTH_TEST);glDepthFunc(GL_LESS);
  unsigned vals[]={0,1,0x3f,0x80,0xfe,0xff};
  int bad=0,total=0;
  for(int o=0;o<8;o++)for(int which=0;which<3;which++)for(int vi=0;vi<6;vi++){
    unsigned v=vals[vi],ref=0x5a,vmask=0x7f,wmask=0x0f|0x30;
    glStencilMask(0xff);glClearStencil(v);glClearDepth(0.5);glClear(GL_STENCIL_BUFFER_BIT|GL_DEPTH_BUFFER_BIT);
    /* which 0: stencil fails (func NEVER); 1: stencil passes, depth fails (z=0.9 -> 0.95 window); 2: both pass */
    glStencilFunc(which==0?GL_NEVER:GL_ALWAYS,ref,vmask);glStencilMask(wmask);
    glStencilOp(which==0?OPS[o]:GL_KEEP,which==1?OPS[o]:GL_KEEP,which==2?OPS[o]:GL_KEEP);
    glBegin(GL_POINTS);glVertex3f(0.5f,0.5f,which==1?-0.9f:0.9f);glEnd();
    glReadPixels(0,0,1,1,GL_STENCIL_INDEX,GL_UNSIGNED_BYTE,st);
    unsigned want=(v&~wmask)|(op(o,ref,v)&wmask)&255; want&=255;
    total++; if(st[0]!=want){bad++;printf("op %d which %d v %02x got %02x want %02x\n",o,which,v,st[0],want);}
  }
  /* function with value mask: ref 0x13 mask 0x0f vs stored 0xf2,0x83,0x14 */
  GLenum F[8]={GL_NEVER,GL_LESS,GL_EQUAL,GL_LEQUAL,GL_GREATER,GL_NOTEQUAL,GL_GEQUAL,GL_ALWAYS};
  glDisable(GL_DEPTH_TEST);glStencilMask(0xff);
  for(int f=0;f<8;f++){int res=0;unsigned sv[3]={0xf2,0x83,0x14};
    for(int k=0;k<3;k++){glClearStencil(sv[k]);glClear(GL_STENCIL_BUFFER_BIT|GL_COLOR_BUFFER_BIT);
      glStencilFunc(F[f],0x13,0x0f);glStencilOp(GL_KEEP,GL_KEEP,GL_KEEP);glBegin(GL_POINTS);glColor3f(1,1,1);glVertex2f(0.5f,0.5f);glEnd();
      glReadPixels(0,0,1,1,GL_RGBA,GL_UNSIGNED_BYTE,buf+512);if(buf[512])res|=1<<k;}
    printf("func %d pass mask %d\n",f,res);}
  printf("ops: %d/%d mismatches\n",bad,total);return 0;}
