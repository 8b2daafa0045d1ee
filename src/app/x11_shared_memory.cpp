#include "app/x11_shared_memory.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <vector>

#include "core/error.hpp"

// X11's headers define None, Bool, Status, Success...: last, and only in this file.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/extensions/XShm.h>
#include <sys/ipc.h>
#include <sys/shm.h>

// GLFW's X11 accessors, as glfw3native.h declares them (that header also wants Xrandr's headers, which
// nothing here needs). Debian's libglfw3 is built for X11; both return 0 when no X11 window is there.
extern "C" {
GLFWAPI Display* glfwGetX11Display(void);
GLFWAPI ::Window glfwGetX11Window(GLFWwindow* window);
}

namespace stipple::app {

namespace {

// Xlib reports a failed request to an error handler, whose default ends the process: a segment the
// server cannot attach (a display on another machine) must be an answer instead.
int g_x_error = 0;
int record_x_error(Display*, XErrorEvent* event) {
    g_x_error = event->error_code;
    return 0;
}

class ErrorTrap {
public:
    explicit ErrorTrap(Display* display) : display_(display) {
        XSync(display_, False);
        g_x_error = 0;
        previous_ = XSetErrorHandler(record_x_error);
    }
    ~ErrorTrap() {
        if (previous_) finish();
    }
    int finish() {  // the error code of the requests since the trap was set (0: none)
        XSync(display_, False);
        XSetErrorHandler(previous_);
        previous_ = nullptr;
        return g_x_error;
    }

private:
    Display* display_;
    int (*previous_)(Display*, XErrorEvent*) = nullptr;
};

struct Segment {
    XShmSegmentInfo info{};
    XImage* image = nullptr;
    unsigned long shown_request = 0;  // the PutImage that last read it (0: none)
};

// A segment the server shares: attached, then marked for removal so that it goes when both sides detach
// (also when the process ends without detaching).
bool attach_segment(Display* display, Visual* visual, int depth, VkExtent2D extent, Segment& segment,
                    std::string* why) {
    segment.image = XShmCreateImage(display, visual, unsigned(depth), ZPixmap, nullptr, &segment.info, extent.width,
                                    extent.height);
    if (!segment.image) return *why = "XShmCreateImage failed", false;
    if (segment.image->bits_per_pixel != 32 || segment.image->bytes_per_line != int(extent.width) * 4) {
        XDestroyImage(segment.image);
        segment.image = nullptr;
        return *why = "the server's shared images are not 32-bit words without padding", false;
    }
    const size_t bytes = size_t(segment.image->bytes_per_line) * extent.height;
    segment.info.shmid = shmget(IPC_PRIVATE, bytes, IPC_CREAT | 0600);
    if (segment.info.shmid < 0) {
        XDestroyImage(segment.image);
        segment.image = nullptr;
        return *why = "shmget of " + std::to_string(bytes) + " bytes failed: " + std::strerror(errno), false;
    }
    segment.info.shmaddr = static_cast<char*>(shmat(segment.info.shmid, nullptr, 0));
    shmctl(segment.info.shmid, IPC_RMID, nullptr);  // freed once detached by both (Linux keeps it while attached)
    if (segment.info.shmaddr == reinterpret_cast<char*>(-1)) {
        segment.info.shmaddr = nullptr;
        XDestroyImage(segment.image);
        segment.image = nullptr;
        return *why = std::string("shmat failed: ") + std::strerror(errno), false;
    }
    segment.image->data = segment.info.shmaddr;
    segment.info.readOnly = False;
    ErrorTrap trap(display);
    const bool attached = XShmAttach(display, &segment.info) && trap.finish() == 0;
    if (!attached) {
        shmdt(segment.info.shmaddr);
        segment.image->data = nullptr;
        XDestroyImage(segment.image);
        segment.image = nullptr;
        return *why = "the X server cannot attach a shared segment (a display on another machine?)", false;
    }
    return true;
}

void detach_segment(Display* display, Segment& segment) {
    if (!segment.image) return;
    XShmDetach(display, &segment.info);
    XDestroyImage(segment.image);  // an XShm image's destructor leaves the segment's memory alone
    shmdt(segment.info.shmaddr);
    segment = Segment{};
}

}  // namespace

struct X11SharedMemory::State {
    Display* display = nullptr;
    ::Window window = 0;
    Visual* visual = nullptr;
    int depth = 0;
    GC gc = nullptr;
    VkExtent2D extent{};
    std::vector<Segment> segments;
};

X11SharedMemory::X11SharedMemory(std::unique_ptr<State> state) : state_(std::move(state)) {}

std::unique_ptr<X11SharedMemory> X11SharedMemory::open(GLFWwindow* window, std::string* why) {
    auto state = std::make_unique<State>();
    state->display = glfwGetX11Display();
    state->window = glfwGetX11Window(window);
    if (!state->display || !state->window) return *why = "the window is not an X11 window", nullptr;
    if (!XShmQueryExtension(state->display)) return *why = "the X server has no MIT-SHM extension", nullptr;
    XWindowAttributes attributes{};
    if (!XGetWindowAttributes(state->display, state->window, &attributes))
        return *why = "cannot read the window's visual", nullptr;
    const Visual* v = attributes.visual;
    // Depth 24 only: a 32-bit visual would take the frame's alpha (the splat's coverage) as transparency.
    if (attributes.depth != 24 || v->c_class != TrueColor || v->red_mask != 0xff0000 || v->green_mask != 0xff00 ||
        v->blue_mask != 0xff || ImageByteOrder(state->display) != LSBFirst)
        return *why = "the window's visual is not 24-bit BGRX true colour", nullptr;
    state->visual = attributes.visual;
    state->depth = attributes.depth;
    // A trial segment: a server on another machine refuses to attach it.
    Segment trial;
    if (!attach_segment(state->display, state->visual, state->depth, {16, 16}, trial, why)) return nullptr;
    detach_segment(state->display, trial);
    state->gc = XCreateGC(state->display, state->window, 0, nullptr);
    if (!state->gc) return *why = "XCreateGC failed", nullptr;
    return std::unique_ptr<X11SharedMemory>(new X11SharedMemory(std::move(state)));
}

X11SharedMemory::~X11SharedMemory() {
    release_segments();
    XFreeGC(state_->display, state_->gc);
    XSync(state_->display, False);
}

void X11SharedMemory::release_segments() {
    if (state_->segments.empty()) return;
    XSync(state_->display, False);  // the server done with every frame before the segments go
    for (Segment& segment : state_->segments) detach_segment(state_->display, segment);
    state_->segments.clear();
}

void X11SharedMemory::resize(VkExtent2D extent, uint32_t count) {
    release_segments();
    state_->extent = extent;
    state_->segments.resize(count);
    for (Segment& segment : state_->segments) {
        std::string why;
        if (!attach_segment(state_->display, state_->visual, state_->depth, extent, segment, &why)) {
            release_segments();
            fail("cannot show the window's frames through X11 shared memory: " + why);
        }
    }
}

void X11SharedMemory::show(uint32_t index, const void* pixels, size_t row_pitch, const PixelsOver& over) {
    Segment& segment = state_->segments.at(index);
    // The server copies from the segment when it handles the request: a later frame written into it
    // before then would tear the earlier one. With two segments it has had a whole frame's time.
    if (segment.shown_request != 0 && LastKnownRequestProcessed(state_->display) < segment.shown_request)
        XSync(state_->display, False);
    const size_t row = size_t(segment.image->bytes_per_line);
    if (row_pitch == row) {
        std::memcpy(segment.image->data, pixels, row * state_->extent.height);
    } else {
        for (uint32_t y = 0; y < state_->extent.height; ++y)
            std::memcpy(segment.image->data + y * row, static_cast<const char*>(pixels) + y * row_pitch, row);
    }
    // The layer over the rows and columns it may cover, in the copy just made (the frame's own memory is
    // left as drawn: screenshots and exports never show the panel).
    const uint32_t width = state_->extent.width, height = state_->extent.height;
    if (over.pixels && over.x < width && over.y < height) {
        const uint32_t columns = std::min(over.width, width - over.x), rows = std::min(over.height, height - over.y);
        for (uint32_t y = over.y; y < over.y + rows; ++y) {
            auto* out = reinterpret_cast<uint32_t*>(segment.image->data + y * row) + over.x;
            const auto* layer = reinterpret_cast<const uint32_t*>(static_cast<const char*>(over.pixels) +
                                                                  y * over.row_pitch) + over.x;
            pixels_over(out, layer, columns);
        }
    }
    segment.shown_request = NextRequest(state_->display);
    XShmPutImage(state_->display, state_->window, state_->gc, segment.image, 0, 0, 0, 0, state_->extent.width,
                 state_->extent.height, False);
    XFlush(state_->display);
}

}  // namespace stipple::app
