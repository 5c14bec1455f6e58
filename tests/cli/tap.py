"""TAP for the command-line tests written in Python: ok(cond, msg) prints one line and counts it,
plan() prints the plan after the last check and returns the exit status (1 when any check failed)."""
import sys

_count = 0
_failed = 0


def ok(cond, msg):
    global _count, _failed
    _count += 1
    _failed += not cond
    print(('ok' if cond else 'not ok') + ' %d - %s' % (_count, msg.replace('\n', ' | ')))
    sys.stdout.flush()


def plan():
    print('1..%d' % _count)
    return 1 if _failed else 0
