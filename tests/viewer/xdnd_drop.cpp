// A drag-and-drop source for the viewer's session tests: drops files and folders on a window as a
// file manager does, through the X drag-and-drop protocol (XDND, version 5), so that the test goes
// through the same path as a user's drop (the X server, GLFW's drop handling, the viewer's
// callback) instead of calling the viewer's code.
//
//   xdnd_drop --title PREFIX [--timeout SECONDS] PATH...
//
// Waits for a window whose title starts with PREFIX (the viewer's "Temporal Styles - " once it has
// named what it shows) and that takes drops (XdndAware), then drops each PATH in turn: XdndEnter
// offering text/uri-list, XdndPosition over the window's centre, XdndDrop; answers the window's
// request for the selection with the file's URI; waits for XdndFinished, then for the window's
// title to change (the viewer names what it opened in it). Prints each new title, then asks the
// window to close (WM_DELETE_WINDOW). Exit 0 when every drop was taken and changed the title, 1
// with a message otherwise.
#include <X11/Xatom.h>
#include <X11/Xlib.h>
#include <poll.h>

#include <array>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr long kXdndVersion = 5;

struct DisplayCloser {
    void operator()(Display* display) const { XCloseDisplay(display); }
};
using DisplayHandle = std::unique_ptr<Display, DisplayCloser>;

struct Atoms {
    explicit Atoms(Display* display)
        : aware(XInternAtom(display, "XdndAware", False)),
          enter(XInternAtom(display, "XdndEnter", False)),
          position(XInternAtom(display, "XdndPosition", False)),
          status(XInternAtom(display, "XdndStatus", False)),
          drop(XInternAtom(display, "XdndDrop", False)),
          finished(XInternAtom(display, "XdndFinished", False)),
          selection(XInternAtom(display, "XdndSelection", False)),
          actionCopy(XInternAtom(display, "XdndActionCopy", False)),
          uriList(XInternAtom(display, "text/uri-list", False)),
          netWmName(XInternAtom(display, "_NET_WM_NAME", False)),
          utf8String(XInternAtom(display, "UTF8_STRING", False)),
          wmProtocols(XInternAtom(display, "WM_PROTOCOLS", False)),
          wmDeleteWindow(XInternAtom(display, "WM_DELETE_WINDOW", False)) {}
    Atom aware, enter, position, status, drop, finished, selection, actionCopy, uriList, netWmName, utf8String,
        wmProtocols, wmDeleteWindow;
};

// file:// URI of an absolute path, every byte outside the unreserved set percent-encoded.
std::string fileUri(const fs::path& path) {
    std::string uri = "file://";
    for (const unsigned char c : fs::absolute(path).lexically_normal().string()) {
        const bool plain = std::isalnum(c) != 0 || c == '/' || c == '-' || c == '_' || c == '.' || c == '~';
        if (plain) {
            uri += char(c);
        } else {
            char escaped[4];
            std::snprintf(escaped, sizeof escaped, "%%%02X", c);
            uri += escaped;
        }
    }
    return uri;
}

std::optional<std::string> windowTitle(Display* display, const Atoms& atoms, Window window) {
    Atom type = None;
    int format = 0;
    unsigned long count = 0, remaining = 0;
    unsigned char* data = nullptr;
    if (XGetWindowProperty(display, window, atoms.netWmName, 0, 4096, False, atoms.utf8String, &type, &format, &count,
                           &remaining, &data) != Success)
        return std::nullopt;
    std::optional<std::string> title;
    if (data != nullptr && type == atoms.utf8String && format == 8)
        title = std::string(reinterpret_cast<const char*>(data), count);
    if (data != nullptr) XFree(data);
    return title;
}

bool takesDrops(Display* display, const Atoms& atoms, Window window) {
    Atom type = None;
    int format = 0;
    unsigned long count = 0, remaining = 0;
    unsigned char* data = nullptr;
    const bool found = XGetWindowProperty(display, window, atoms.aware, 0, 1, False, AnyPropertyType, &type, &format,
                                          &count, &remaining, &data) == Success &&
                       type != None && count == 1;
    if (data != nullptr) XFree(data);
    return found;
}

std::optional<Window> findWindow(Display* display, const Atoms& atoms, Window parent, const std::string& prefix) {
    Window root = 0, parentOfParent = 0;
    Window* children = nullptr;
    unsigned int count = 0;
    if (XQueryTree(display, parent, &root, &parentOfParent, &children, &count) == 0) return std::nullopt;
    std::optional<Window> found;
    for (unsigned int i = 0; i < count && !found; ++i) {
        const std::optional<std::string> title = windowTitle(display, atoms, children[i]);
        if (title && title->rfind(prefix, 0) == 0 && takesDrops(display, atoms, children[i]))
            found = children[i];
        else
            found = findWindow(display, atoms, children[i], prefix);
    }
    if (children != nullptr) XFree(children);
    return found;
}

// Waits until `done` says so, handing every event to it; false when `deadline` passes first.
bool waitFor(Display* display, Clock::time_point deadline, const std::function<bool(const XEvent*)>& done) {
    while (Clock::now() < deadline) {
        while (XPending(display) > 0) {
            XEvent event;
            XNextEvent(display, &event);
            if (done(&event)) return true;
        }
        if (done(nullptr)) return true;
        pollfd connection{ConnectionNumber(display), POLLIN, 0};
        poll(&connection, 1, 50);
    }
    return false;
}

void sendClientMessage(Display* display, Window target, Atom type, const std::array<long, 5>& data) {
    XEvent event{};
    event.xclient.type = ClientMessage;
    event.xclient.display = display;
    event.xclient.window = target;
    event.xclient.message_type = type;
    event.xclient.format = 32;
    for (int i = 0; i < 5; ++i) event.xclient.data.l[i] = data[std::size_t(i)];
    XSendEvent(display, target, False, NoEventMask, &event);
    XFlush(display);
}

// The window's request for the dropped data: the URI list, as text/uri-list.
void answerSelectionRequest(Display* display, const Atoms& atoms, const XSelectionRequestEvent& request,
                            const std::string& uriList) {
    XEvent reply{};
    reply.xselection.type = SelectionNotify;
    reply.xselection.display = display;
    reply.xselection.requestor = request.requestor;
    reply.xselection.selection = request.selection;
    reply.xselection.target = request.target;
    reply.xselection.time = request.time;
    reply.xselection.property = None;
    if (request.target == atoms.uriList && request.property != None) {
        XChangeProperty(display, request.requestor, request.property, atoms.uriList, 8, PropModeReplace,
                        reinterpret_cast<const unsigned char*>(uriList.data()), int(uriList.size()));
        reply.xselection.property = request.property;
    }
    XSendEvent(display, request.requestor, False, NoEventMask, &reply);
    XFlush(display);
}

// One drop of `path` on `target`, as a file manager makes it.
void dropPath(Display* display, const Atoms& atoms, Window source, Window target, const fs::path& path,
              Clock::time_point deadline) {
    const std::string uriList = fileUri(path) + "\r\n";
    XSetSelectionOwner(display, atoms.selection, source, CurrentTime);

    XWindowAttributes attributes{};
    XGetWindowAttributes(display, target, &attributes);
    int rootX = 0, rootY = 0;
    Window child = 0;
    XTranslateCoordinates(display, target, DefaultRootWindow(display), attributes.width / 2, attributes.height / 2,
                          &rootX, &rootY, &child);

    sendClientMessage(display, target, atoms.enter, {long(source), kXdndVersion << 24, long(atoms.uriList), 0, 0});
    sendClientMessage(display, target, atoms.position,
                      {long(source), 0, (long(rootX) << 16) | long(rootY), CurrentTime, long(atoms.actionCopy)});
    bool accepted = false;
    if (!waitFor(display, deadline, [&](const XEvent* event) {
            if (event == nullptr || event->type != ClientMessage || event->xclient.message_type != atoms.status)
                return false;
            accepted = (event->xclient.data.l[1] & 1) != 0;
            return true;
        }))
        throw std::runtime_error("the window did not answer XdndPosition with XdndStatus");
    if (!accepted) throw std::runtime_error("the window refuses a drop of text/uri-list");

    sendClientMessage(display, target, atoms.drop, {long(source), 0, CurrentTime, 0, 0});
    bool finishedWithSuccess = false;
    if (!waitFor(display, deadline, [&](const XEvent* event) {
            if (event == nullptr) return false;
            if (event->type == SelectionRequest) answerSelectionRequest(display, atoms, event->xselectionrequest, uriList);
            if (event->type != ClientMessage || event->xclient.message_type != atoms.finished) return false;
            // The protocol has bit 0 say the drop was taken; GLFW puts there the number of bytes
            // it read, so anything but 0 is success.
            finishedWithSuccess = event->xclient.data.l[1] != 0;
            return true;
        }))
        throw std::runtime_error("the window did not finish the drop (no XdndFinished)");
    if (!finishedWithSuccess) throw std::runtime_error("the window finished the drop without taking it");
}

int run(int argc, char** argv) {
    std::string prefix;
    double timeoutSeconds = 60;
    std::vector<fs::path> paths;
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (argument == "--title" && i + 1 < argc)
            prefix = argv[++i];
        else if (argument == "--timeout" && i + 1 < argc)
            timeoutSeconds = std::stod(argv[++i]);
        else
            paths.emplace_back(argument);
    }
    if (prefix.empty() || paths.empty())
        throw std::runtime_error("usage: xdnd_drop --title PREFIX [--timeout SECONDS] PATH...");
    const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                             std::chrono::duration<double>(timeoutSeconds));

    const DisplayHandle display(XOpenDisplay(nullptr));
    if (!display) throw std::runtime_error("cannot open the X display (is DISPLAY set?)");
    const Atoms atoms(display.get());
    std::optional<Window> target;
    if (!waitFor(display.get(), deadline, [&](const XEvent*) {
            target = findWindow(display.get(), atoms, DefaultRootWindow(display.get()), prefix);
            return target.has_value();
        }))
        throw std::runtime_error("no window titled '" + prefix + "...' that takes drops appeared");
    // The source of the drag: an unmapped window of our own, which owns the XDND selection.
    const Window source = XCreateSimpleWindow(display.get(), DefaultRootWindow(display.get()), 0, 0, 1, 1, 0, 0, 0);

    for (const fs::path& path : paths) {
        const std::string before = windowTitle(display.get(), atoms, *target).value_or("");
        dropPath(display.get(), atoms, source, *target, path, deadline);
        std::string after = before;
        if (!waitFor(display.get(), deadline, [&](const XEvent*) {
                after = windowTitle(display.get(), atoms, *target).value_or("");
                return after != before;
            }))
            throw std::runtime_error("the drop of " + path.string() + " was taken, but the title stayed '" + before +
                                     "'");
        std::printf("dropped %s: the window is now titled '%s'\n", path.c_str(), after.c_str());
        std::fflush(stdout);
    }
    sendClientMessage(display.get(), *target, atoms.wmProtocols, {long(atoms.wmDeleteWindow), CurrentTime, 0, 0, 0});
    XDestroyWindow(display.get(), source);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "xdnd_drop: %s\n", error.what());
        return 1;
    }
}
