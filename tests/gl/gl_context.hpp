#pragma once
// An offscreen OpenGL context for tests that draw by hand (Mesa llvmpipe under xvfb-run -a in CI).
#include <string>
#include <vector>

#include <vtkNew.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLQuadHelper.h>
#include <vtkOpenGLRenderUtilities.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLState.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkSmartPointer.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

namespace lucent_test {

/// Draws a full-screen quad with one fragment shader into a width x height RGBA32F target and reads
/// it back. The shader sees `in vec2 texCoord` (texel centres) and writes gl_FragData[0].
class QuadProbe {
 public:
  QuadProbe(int width, int height) : mWidth(width), mHeight(height) {
    mWindow->SetOffScreenRendering(1);
    mWindow->SetSize(8, 8);
    mWindow->AddRenderer(mRenderer);
    mWindow->Render();  // creates the context
    mGl = vtkOpenGLRenderWindow::SafeDownCast(mWindow);
    mGl->MakeCurrent();
    mTarget->SetContext(mGl);
    mTarget->Allocate2D(unsigned(width), unsigned(height), 4, VTK_FLOAT);
    mFbo->SetContext(mGl);
  }
  ~QuadProbe() {
    delete mQuad;
    mTarget->ReleaseGraphicsResources(mWindow);
    mFbo->ReleaseGraphicsResources(mWindow);
  }

  /// Compiles @p fragmentShader (once); false when it does not compile.
  bool program(const std::string& fragmentShader) {
    mGl->MakeCurrent();
    delete mQuad;
    mQuad = new vtkOpenGLQuadHelper(
        mGl, vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(),
        fragmentShader.c_str(), "");
    return mQuad->Program && mQuad->Program->GetCompiled();
  }
  vtkShaderProgram* shader() { return mQuad->Program; }
  vtkOpenGLRenderWindow* window() { return mGl; }

  /// Draws and returns width * height * 4 floats.
  std::vector<float> draw() {
    mGl->MakeCurrent();
    vtkOpenGLState* state = mGl->GetState();
    mFbo->SaveCurrentBindingsAndBuffers();
    mFbo->Bind();
    mFbo->AddColorAttachment(0, mTarget);
    mFbo->ActivateDrawBuffers(1);
    state->vtkglViewport(0, 0, mWidth, mHeight);
    state->vtkglScissor(0, 0, mWidth, mHeight);
    state->vtkglDisable(GL_BLEND);
    state->vtkglDisable(GL_DEPTH_TEST);
    mQuad->Render();
    std::vector<float> out(std::size_t(mWidth) * std::size_t(mHeight) * 4);
    mFbo->ActivateReadBuffer(0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, mWidth, mHeight, GL_RGBA, GL_FLOAT, out.data());
    mFbo->UnBind();
    mFbo->RestorePreviousBindingsAndBuffers();
    return out;
  }

 private:
  int mWidth, mHeight;
  vtkNew<vtkRenderWindow> mWindow;
  vtkNew<vtkRenderer> mRenderer;
  vtkOpenGLRenderWindow* mGl = nullptr;
  vtkNew<vtkTextureObject> mTarget;
  vtkNew<vtkOpenGLFramebufferObject> mFbo;
  vtkOpenGLQuadHelper* mQuad = nullptr;
};

}  // namespace lucent_test
