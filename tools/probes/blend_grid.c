/* Blend grid probe: every 17th 8-bit value for each of the 15x15 factor pairs and 5 equations
 * (MIN/MAX once), blended with glDrawPixels over a glDrawPixels background; writes src, dst and
 * each result plane (256x256 RGBA8) to $OUT. In 2026-11 the integer path of src/fragment/blend.rs
 * reproduced every byte of Mesa 22 llvmpipe's dump (877 configurations x 65536 pixels); once blending
 * is wired into spans, the capi tests compare it with Mesa directly.
 * gcc tools/probes/blend_grid.c -lOSMesa -o /tmp/blend_grid && OUT=/tmp/blend.bin /tmp/blend_grid */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#define W 256
static const GLenum F[15]={GL_ZERO,GL_ONE,GL_SRC_COLOR,GL_ONE_MINUS_SRC_COLOR,GL_DST_COLOR,GL_ONE_MINUS_DST_COLOR,GL_SRC_ALPHA,GL_ONE_MINUS_SRC_ALPHA,GL_DST_ALPHA,GL_ONE_MINUS_DST_ALPHA,GL_CONSTANT_COLOR,GL_ONE_MINUS_CONSTANT_COLOR,GL_CONSTANT_ALPHA,GL_ONE_MINUS_CONSTANT_ALPHA,GL_SRC_ALPHA_SATURATE};
static const GLenum E[5]={GL_FUNC_ADD,GL_FUNC_SUBTRACT,GL_FUNC_REVERSE_SUBTRACT,GL_MIN,GL_MAX};
typedef void (*PFNBE)(GLenum);
typedef void (*PFNBC)(GLfloat,GLfloat,GLfloat,GLfloat);
int main(void){
  OSMesaContext c=OSMesaCreateContextExt(OSMESA_RGBA,0,0,0,NULL);
  static unsigned char buf[W*W*4], target[W*W*4], src[W*W*4], dst[W*W*4];
  OSMesaMakeCurrent(c,target,GL_UNSIGNED_BYTE,W,W);
  PFNBE be=(PFNBE)OSMesaGetProcAddress("glBlendEquation");
  PFNBC bc=(PFNBC)OSMesaGetProcAddress("glBlendColor");
  for(int y=0;y<W;y++)for(int x=0;x<W;x++){
    int v0=(x&15)*17,v1=(x>>4)*17,u0=(y&15)*17,u1=(y>>4)*17;
    unsigned char *s=src+(y*W+x)*4,*d=dst+(y*W+x)*4;
    s[0]=v0;s[1]=v1;s[2]=255-v0;s[3]=v1;
    d[0]=u0;d[1]=u1;d[2]=((y*7)&15)*17;d[3]=u1;
  }
  glViewport(0,0,W,W);glMatrixMode(GL_PROJECTION);glLoadIdentity();glOrtho(0,W,0,W,-1,1);
  glDisable(GL_DITHER);glPixelStorei(GL_UNPACK_ALIGNMENT,1);glPixelStorei(GL_PACK_ALIGNMENT,1);
  bc(0.2f,0.4f,0.6f,0.8f);
  FILE*o=fopen(getenv("OUT"),"wb");
  fwrite(src,1,sizeof src,o);fwrite(dst,1,sizeof dst,o);
  for(int e=0;e<5;e++)for(int s=0;s<15;s++)for(int d=0;d<15;d++){
    if(e>=3&&(s||d))continue;
    glDisable(GL_BLEND);glRasterPos2i(0,0);glDrawPixels(W,W,GL_RGBA,GL_UNSIGNED_BYTE,dst);
    glEnable(GL_BLEND);be(E[e]);glBlendFunc(F[s],F[d]);
    glDrawPixels(W,W,GL_RGBA,GL_UNSIGNED_BYTE,src);
    glReadPixels(0,0,W,W,GL_RGBA,GL_UNSIGNED_BYTE,buf);
    fwrite(buf,1,sizeof buf,o);
  }
  /* Separate RGB/alpha functions: 200 pseudo-random tuples, each written as six indices
   * (src rgb, dst rgb, src alpha, dst alpha, equation rgb, equation alpha) then its plane. */
  typedef void (*PFNBFS)(GLenum,GLenum,GLenum,GLenum);
  typedef void (*PFNBES)(GLenum,GLenum);
  PFNBFS bfs=(PFNBFS)OSMesaGetProcAddress("glBlendFuncSeparate");
  PFNBES bes=(PFNBES)OSMesaGetProcAddress("glBlendEquationSeparate");
  unsigned seed=12345;
  for(int n=0;n<200;n++){
    unsigned char t[6];
    for(int k=0;k<6;k++){seed=seed*1103515245u+12345u;t[k]=(seed>>16)%(k<4?15:5);}
    glDisable(GL_BLEND);glRasterPos2i(0,0);glDrawPixels(W,W,GL_RGBA,GL_UNSIGNED_BYTE,dst);
    glEnable(GL_BLEND);bes(E[t[4]],E[t[5]]);bfs(F[t[0]],F[t[1]],F[t[2]],F[t[3]]);
    glDrawPixels(W,W,GL_RGBA,GL_UNSIGNED_BYTE,src);
    glReadPixels(0,0,W,W,GL_RGBA,GL_UNSIGNED_BYTE,buf);
    fwrite(t,1,6,o);fwrite(buf,1,sizeof buf,o);
  }
  fclose(o);printf("err %x\n",glGetError());return 0;}
