"""Who may use the studio, and which files it serves. Pure functions, no ROS, no server.

On the loopback interface only this machine's users can reach the page, as with gzclient, so
no token is needed. Bound to any other address, the page would hand the simulator to anyone on
the network, so (as Jupyter does) a random token is made, printed in the URL, and every request
and websocket without it is refused with 403.
"""
import hmac
import ipaddress
import os
import secrets

TOKEN_COOKIE = "sim_studio_token"


def is_loopback(host):
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


def choose_token(host, given=""):
    """The token a request must carry: the one given, else a new random one off loopback,
    else none ("")."""
    if given:
        return given
    return "" if is_loopback(host) else secrets.token_urlsafe(24)


def page_url(host, port, token):
    shown = "127.0.0.1" if host in ("0.0.0.0", "::") else host
    if ":" in shown:
        shown = "[%s]" % shown
    return "http://%s:%d/%s" % (shown, port, "?token=" + token if token else "")


def token_accepted(expected, *offered):
    """Whether any offered token (query, cookie, header; None when absent) is the expected one;
    compared in constant time."""
    if not expected:
        return True
    return any(o is not None and hmac.compare_digest(o.encode(), expected.encode()) for o in offered)


def file_under(root, relative):
    """The path of `relative` inside `root`, or None when it would leave `root` (../, an absolute
    path) or is not a regular file. Symlinks inside `root` are followed: the roots are our own
    folders and Debian's (libjs-three links its files into /usr/share/nodejs), and no request
    can make one."""
    if "\0" in relative or "\\" in relative:
        return None
    root = os.path.abspath(root)
    path = os.path.normpath(os.path.join(root, relative.lstrip("/")))
    if os.path.commonpath([root, path]) != root or not os.path.isfile(path):
        return None
    return path
