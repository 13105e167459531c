"""The walkthroughs' shared fixture: a new user's home for each walkthrough file."""
import pytest

from ros_cli import simulator_running
from user_session import UserSession


@pytest.fixture(scope='module')
def user(request, tmp_path_factory):
    """A UserSession for the module (its tests are the tutorial's steps, in order), on a virtual
    screen when the module sets SCREEN = True (its tutorial opens rviz)."""
    assert not simulator_running(), 'a simulator is already running: the walkthrough needs the machine to itself'
    name = request.module.__name__.split('_', 2)[-1]  # test_003_pioneer_report -> pioneer_report
    session = UserSession(tmp_path_factory.mktemp(name), name)
    if getattr(request.module, 'SCREEN', False):
        session.screen()
    yield session
    session.close()
