// view_input: mjbuoy-view's keyboard and mouse, after MuJoCo's simulate
#include <cstdio>

#include "view.h"

namespace mjbview {
namespace {

View* self(GLFWwindow* w) { return static_cast<View*>(glfwGetWindowUserPointer(w)); }

void key(GLFWwindow* w, int k, int, int act, int mods) {
  View* v = self(w);
  if (act == GLFW_RELEASE) return;
  UiLock lk(v);
  switch (k) {
    case GLFW_KEY_SPACE:
      if (act == GLFW_PRESS) v->paused = !v->paused;
      v->steps = 0;
      break;
    case GLFW_KEY_RIGHT:
      if (v->paused) v->steps++;
      break;
    case GLFW_KEY_BACKSPACE:
      if (act == GLFW_PRESS) {
        v->reset = true;
        v->steps = 0;  // steps asked for before the reset are void
        v->pert.active = 0;
        v->frame = true;
      }
      break;
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT:
      if (v->slow + 1 < kNSlow) v->slow++;
      break;
    case GLFW_KEY_EQUAL:
    case GLFW_KEY_KP_ADD:
      if (v->slow > 0) v->slow--;
      break;
    case GLFW_KEY_F:
      if (act == GLFW_PRESS) v->forces = !v->forces;
      break;
    case GLFW_KEY_W:
      if (act == GLFW_PRESS) v->wet = !v->wet;
      break;
    case GLFW_KEY_H:
    case GLFW_KEY_F1:
      if (act == GLFW_PRESS) v->help = !v->help;
      break;
    case GLFW_KEY_Q:
      if (mods & GLFW_MOD_CONTROL) glfwSetWindowShouldClose(w, GLFW_TRUE);
      break;
    case GLFW_KEY_UP:  // drive the chosen actuator, as simulate's control sliders
    case GLFW_KEY_DOWN:
      if (v->act < v->m->nu) {
        double& c = v->ctrl[v->act];
        c = nudgeCtrl(v->m, v->act, c, k == GLFW_KEY_UP ? 1 : -1);
      }
      break;
    case GLFW_KEY_RIGHT_BRACKET:  // next / previous actuator
    case GLFW_KEY_LEFT_BRACKET:
      if (act == GLFW_PRESS && v->m->nu > 0) {
        v->act = (v->act + (k == GLFW_KEY_RIGHT_BRACKET ? 1 : v->m->nu - 1)) % v->m->nu;
      }
      break;
    case GLFW_KEY_0:  // every control back to 0
      if (act == GLFW_PRESS) {
        for (double& c : v->ctrl) c = 0;
      }
      break;
    case GLFW_KEY_ESCAPE:  // back to the free camera
      if (act == GLFW_PRESS) v->cam.type = mjCAMERA_FREE;
      break;
    default:
      break;
  }
}

// double-click: left selects the body under the mouse (mjv_select), right
// moves the camera's look-at point there; as simulate does
void select(View* v, int button, double x, double y) {
  int ww, wh;
  glfwGetWindowSize(v->win, &ww, &wh);
  if (ww <= 0 || wh <= 0) return;
  mjtNum pnt[3];
  int geom = -1, skin = -1;
  UiLock lk(v);
  int body = mjv_select(v->m, v->d, &v->opt, (mjtNum)ww / wh, x / ww, (wh - y) / wh, &v->scn,
                        pnt, &geom, &skin);
  if (button == GLFW_MOUSE_BUTTON_RIGHT) {
    if (body >= 0) mju_copy3(v->cam.lookat, pnt);
    return;
  }
  if (body > 0) {
    v->pert.select = body;
    v->pert.skinselect = skin;
    mjtNum tmp[3];
    mju_sub3(tmp, pnt, v->d->xpos + 3 * body);
    mju_mulMatTVec(v->pert.localpos, v->d->xmat + 9 * body, tmp, 3, 3);
    std::printf("mjbuoy-view: selected body %s\n", mj_id2name(v->m, mjOBJ_BODY, body));
  } else {
    v->pert.select = 0;
    v->pert.skinselect = -1;
    std::printf("mjbuoy-view: selection cleared\n");
  }
  std::fflush(stdout);
}

void button(GLFWwindow* w, int bt, int act, int mods) {
  View* v = self(w);
  v->left = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  v->right = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
  v->middle = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
  glfwGetCursorPos(w, &v->lastx, &v->lasty);
  if (act == GLFW_RELEASE) {
    if (!v->left && !v->right) {
      UiLock lk(v);
      v->pert.active = 0;
    }
    return;
  }
  double now = glfwGetTime();
  if (bt == v->lastButton && now - v->lastPress < 0.4) {
    select(v, bt, v->lastx, v->lasty);
    v->lastPress = -10;
    return;
  }
  v->lastPress = now;
  v->lastButton = bt;
  // ctrl + drag on a selected body: perturb it (right: translate, left: rotate)
  if ((mods & GLFW_MOD_CONTROL) && (bt == GLFW_MOUSE_BUTTON_LEFT || bt == GLFW_MOUSE_BUTTON_RIGHT)) {
    UiLock lk(v);
    if (v->pert.select > 0) {
      int kind = bt == GLFW_MOUSE_BUTTON_RIGHT ? mjPERT_TRANSLATE : mjPERT_ROTATE;
      if (!v->pert.active) mjv_initPerturb(v->m, v->d, &v->scn, &v->pert);
      v->pert.active = kind;
    }
  }
}

void move(GLFWwindow* w, double x, double y) {
  View* v = self(w);
  if (!v->left && !v->right && !v->middle) return;
  double dx = x - v->lastx, dy = y - v->lasty;
  v->lastx = x;
  v->lasty = y;
  int ww, wh;
  glfwGetWindowSize(w, &ww, &wh);
  if (wh <= 0) return;
  bool shift = glfwGetKey(w, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
               glfwGetKey(w, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
  int action = v->right ? (shift ? mjMOUSE_MOVE_H : mjMOUSE_MOVE_V)
             : v->left  ? (shift ? mjMOUSE_ROTATE_H : mjMOUSE_ROTATE_V)
                        : mjMOUSE_ZOOM;
  UiLock lk(v);
  if (v->pert.active) {
    mjv_movePerturb(v->m, v->d, action, dx / wh, dy / wh, &v->scn, &v->pert);
  } else {
    mjv_moveCamera(v->m, action, dx / wh, dy / wh, &v->scn, &v->cam);
    v->frame = false;
  }
}

void scroll(GLFWwindow* w, double, double yoff) {
  View* v = self(w);
  mjv_moveCamera(v->m, mjMOUSE_ZOOM, 0, -0.05 * yoff, &v->scn, &v->cam);
  v->frame = false;
}

}  // namespace

void installInput(View* v) {
  glfwSetWindowUserPointer(v->win, v);
  glfwSetKeyCallback(v->win, key);
  glfwSetMouseButtonCallback(v->win, button);
  glfwSetCursorPosCallback(v->win, move);
  glfwSetScrollCallback(v->win, scroll);
}

}  // namespace mjbview
