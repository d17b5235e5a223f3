/* Probe for the fragment stages (run on Mesa: gcc tools/probes/logic_op_grid.c -lOSMesa && ./a.out); see src/fragment/. */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>
#define W 256
int main(void){
  static unsigned char buf[W*W*4],tgt[W*W*4],src[W*W*4],dst[W*W*4];
  for(int p=0;p<2;p++){
  OSMesaContext c=OSMesaCreateContextExt(p?OSMESA_RGB_565:OSMESA_RGBA,0,0,0,NULL);
  OSMesaMakeCurrent(c,tgt,p?GL_UNSIGNED_SHORT_5_6_5:GL_UNSIGNED_BYTE,W,W);
  for(int i=0;i<W*W;i++){int x=i%W,y=i/W;unsigned char*s=src+i*4,*d=dst+i*4;s[0]=x;s[1]=y;s[2]=x^0x5a;s[3]=255-x;d[0]=y;d[1]=x;d[2]=y^0xa5;d[3]=x^y;}
  glViewport(0,0,W,W);glMatrixMode(GL_PROJECTION);glLoadIdentity();glOrtho(0,W,0,W,-1,1);glDisable(GL_DITHER);
  int bad[16]={0};
  for(int op=0;op<16;op++){
    glDisable(GL_COLOR_LOGIC_OP);glRasterPos2i(0,0);glDrawPixels(W,W,GL_RGBA,GL_UNSIGNED_BYTE,dst);
    glEnable(GL_COLOR_LOGIC_OP);glLogicOp(GL_CLEAR+op);glDrawPixels(W,W,GL_RGBA,GL_UNSIGNED_BYTE,src);
    if(!p){glReadPixels(0,0,W,W,GL_RGBA,GL_UNSIGNED_BYTE,buf);
      for(int i=0;i<W*W*4;i++){unsigned s=src[i],d=dst[i];unsigned r=((s&d&-(op&1))|(s&~d&-((op>>1)&1))|(~s&d&-((op>>2)&1))|(~s&~d&-((op>>3)&1)))&255;if(buf[i]!=r)bad[op]++;}
    } else {
      glFinish(); unsigned short *t=(unsigned short*)tgt;
      for(int i=0;i<W*W;i++){unsigned char*s=src+i*4,*d=dst+i*4;
        unsigned sw=(s[0]>>3)<<11|(s[1]>>2)<<5|(s[2]>>3), dw=(d[0]>>3)<<11|(d[1]>>2)<<5|(d[2]>>3);
        unsigned r=((sw&dw&-(op&1))|(sw&~dw&-((op>>1)&1))|(~sw&dw&-((op>>2)&1))|(~sw&~dw&-((op>>3)&1)))&0xffff;
        if(t[i]!=r){if(!bad[op])printf("565 op %d i %d src %04x dst %04x got %04x want %04x\n",op,i,sw,dw,t[i],r);bad[op]++;}}
    }
  }
  printf("%s mismatches per op:",p?"RGB565":"RGBA8");for(int op=0;op<16;op++)printf(" %d",bad[op]);printf("\n");
  OSMesaDestroyContext(c);}
  return 0;}
