"""A page's joint command -> bullet_sim_msgs/JointCmd, as Gazebo's joint panel fills its
msgs::JointCmd: a force held until changed, a position target with its PID, a velocity target
with its PID, or a reset. Bad numbers are refused with the field's name; nothing is sent."""
from bullet_sim_msgs.msg import JointCmd, Pid

from sim_studio import request_fields

PID_FIELDS = ("target", "p", "i", "d")


def pid(fields):
    """A Pid from {"target", "p", "i", "d"} (the panel's fields). The integral's and the
    output's bounds stay 0: no bound, as the panel sets none."""
    values = {f: request_fields.number(fields, f, 0.0 if f != "target" else None) for f in PID_FIELDS}
    return Pid(target=values["target"], p=values["p"], i=values["i"], d=values["d"])


def joint_cmd(model, joint, message):
    """The JointCmd for "model::joint" from a page's "command" message: any of "force"
    (number), "position" and "velocity" ({target, p, i, d}), "reset" (true)."""
    cmd = JointCmd(name="%s::%s" % (model, joint))
    cmd.reset = message.get("reset") is True
    if message.get("force") is not None:
        cmd.set_force, cmd.force = True, request_fields.number(message, "force")
    for kind in ("position", "velocity"):
        if message.get(kind) is not None:
            if not isinstance(message[kind], dict):
                raise ValueError("%s: expected an object with %s" % (kind, ", ".join(PID_FIELDS)))
            try:
                setattr(cmd, kind, pid(message[kind]))
            except ValueError as e:
                raise ValueError("%s.%s" % (kind, e)) from None
            setattr(cmd, "set_" + kind, True)
    if not (cmd.reset or cmd.set_force or cmd.set_position or cmd.set_velocity):
        raise ValueError("a joint command needs one of force, position, velocity or reset")
    return cmd
