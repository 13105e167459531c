"""The simulator's /gazebo services as the studio's views call them: from the server's worker
threads (Studio.blocking), several views and pages at once, while the simulator may come and go.

One persistent connection per service: the Models and Joints views poll joint positions a few
times a second, and a fresh rospy.ServiceProxy asks the master for the service and opens a TCP
connection on every call. rospy's persistent proxy is not thread-safe, so each has a lock. When
the simulator restarts the connection breaks; the call is tried once more on a new one.

A failure is a ValueError whose text the page shows: the service missing ("is the simulator
running?") or the simulator's own status_message for a request it refused.
"""
import functools
import threading

import rosgraph
import rospy

NAMESPACE = "/gazebo"
WAIT_FOR_SERVICE = 2.0  # s: a page waits on this; the simulator answers in milliseconds when up


class GazeboServices:
    """`run_blocking` (Studio.blocking) runs a blocking call off the server's loop: `request`
    awaits one there; `call` is the blocking call itself."""

    def __init__(self, run_blocking, namespace=NAMESPACE):
        self._run_blocking = run_blocking
        self._namespace = namespace
        self._proxies = {}
        self._locks = {}
        self._guard = threading.Lock()

    async def request(self, name, service_type, check=True, **fields):
        """`call` on a worker thread, awaited."""
        return await self._run_blocking(functools.partial(self.call, name, service_type, check, **fields))

    async def offered(self, name):
        return await self._run_blocking(self.offers, name)

    def call(self, name, service_type, check=True, **fields):
        """Call /gazebo/<name> with `fields`; the response. With `check`, a response whose
        `success` is false raises ValueError with its status_message."""
        with self._guard:
            lock = self._locks.setdefault(name, threading.Lock())
        with lock:
            response = self._call_locked(name, service_type, fields)
        if check and getattr(response, "success", True) is False:
            raise ValueError(response.status_message or "%s/%s failed" % (self._namespace, name))
        return response

    def _call_locked(self, name, service_type, fields):
        full = "%s/%s" % (self._namespace, name)
        for attempt in (1, 2):
            proxy = self._proxies.get(name)
            if proxy is None:
                try:
                    rospy.wait_for_service(full, timeout=WAIT_FOR_SERVICE)
                except rospy.ROSException:
                    raise ValueError("the simulator does not offer %s (is it running?)" % full) from None
                except rospy.ROSInterruptException:
                    raise ValueError("the studio is shutting down") from None
                proxy = self._proxies[name] = rospy.ServiceProxy(full, service_type, persistent=True)
            try:
                return proxy(**fields)
            except (rospy.ServiceException, rospy.exceptions.TransportTerminated, OSError) as e:
                proxy.close()
                del self._proxies[name]
                if attempt == 2:  # a second broken connection: the simulator is gone, not restarted
                    raise ValueError("%s failed: %s" % (full, e)) from None
        raise AssertionError("unreachable")

    def offers(self, name):
        """Whether the simulator offers /gazebo/<name> now (one question to the master, no
        waiting): for services a simulator may lack, such as get_link_properties."""
        try:
            rosgraph.Master(rospy.get_name()).lookupService("%s/%s" % (self._namespace, name))
            return True
        except (rosgraph.MasterException, OSError):
            return False

    def close(self):
        with self._guard:
            for proxy in self._proxies.values():
                proxy.close()
            self._proxies.clear()
