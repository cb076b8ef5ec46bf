"""Coordinate systems and offsets: G54..G59.3, G92, G10, G28/G30, G53, G68, tool length."""
from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import contextmanager

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.machine import tables as t
from edingcnc_lang.events import RotationEvent
from edingcnc_lang.machine.geometry import TURNED_AXES, rotate_about
from edingcnc_lang.machine.state import (
    AXIS_INDEX,
    G_10,
    G_28,
    G_30,
    G_69,
    G_91,
    G_92,
    G_92_1,
    G_92_2,
    G_92_3,
    LINEAR_AXES,
    PLANE_OF,
    MachineState,
    format_value,
)
from edingcnc_lang.machine.parts import Turn

# G68 I1 / J1 / K1: the rotation axis X, Y or Z, so the plane YZ, XZ or XY (manual 3.6.17).
G68_AXIS_WORDS = {"I": "YZ", "J": "XZ", "K": "XY"}
# #5194 angle XY, #5195 YZ, #5196 XZ (manual 3.1)
G68_ANGLE_PARAM = {"XY": 4, "YZ": 5, "XZ": 6}


class CoordinateSystems(MachineState):
    """Turns the axis words of a line into machine positions and back; ``offset()`` is cached until
    a parameter it depends on changes."""

    def _offsets_changed(self) -> None:
        """An offset changed (G5x, G10, G92.., G43, a macro's write): under G68 the pivot moves with
        the offsets, so the current point is re-expressed about the new pivot and the machine stays."""
        turn = self.rotation.turn
        pivot = self._rotation_pivot() if turn is not None and self.offsets.cached is not None else None
        self.offsets.cached = None
        system = self.params.values[t.COORD_SYSTEM]  # a macro may select the system by writing #5220
        if system == int(system) and 1 <= system <= 9:
            self.modal["coord_system"] = t.COORD_SYSTEM_CODES[int(system) - 1]
        if pivot is not None and turn is not None:
            moved = self._rotation_pivot()  # recomputes the offset and tells the rotation stage
            if moved != pivot:
                angle, plane = turn.angle, turn.plane
                here = rotate_about(self.pos, pivot, angle, plane)
                self.pos = list(rotate_about(here, moved, -angle, plane))

    def _offset_reading(self, reading: Mapping[int, float], base: list[float]) -> list[float]:
        """The offset (machine minus work) with which the current point, the machine staying put,
        reads ``reading`` on the given axes; the others read what they read with ``base``.  Under
        G68 the reading is taken through the rotation (whose pivot moves with the offset), so X and
        Y are solved together."""
        turn = self.rotation.turn
        if turn is None:
            return [self.pos[i] - reading[i] if i in reading else b for i, b in enumerate(base)]
        pivot, angle, plane = turn
        here = rotate_about(self.pos, self._rotation_pivot(), angle, plane)
        work = list(rotate_about([h - b for h, b in zip(here, base)], pivot, -angle, plane))
        for axis, number in reading.items():
            work[axis] = number
        return [h - w for h, w in zip(here, rotate_about(work, pivot, angle, plane))]

    def _solved_axes(self, axes: Mapping[int, float]) -> set[int]:
        """The axes whose offset G92/G10 L20 set: the programmed ones, and both axes G68 turns."""
        turn = self.rotation.turn
        turned = set(TURNED_AXES[turn.plane]) if turn is not None else set()
        return set(axes) | (turned if axes.keys() & turned else set())

    def offset(self) -> list[float]:
        """Machine minus work position: G5x + G92 (if active) + tool length on Z, and X on a lathe (G43),
        + the selected spindle's offsets."""
        state = self.offsets
        if state.cached is None:
            values = self.params.values
            system = int(values[t.COORD_SYSTEM]) if 1 <= values[t.COORD_SYSTEM] <= 9 else 1
            off = [values[t.coord_offset_param(system, i)] for i in range(6)]
            if state.g92_active:
                off = [o + values[t.G92_OFFSET + i] for i, o in enumerate(off)]
            off[2] += state.tool_z
            off[0] += state.tool_x
            for axis, shift in enumerate(self.spindle_offset):  # an alternate spindle (M91..M97)
                off[axis] += shift
            state.cached = off
            if self.rotation.turn is not None:
                self._sync_rotation(off)
        return state.cached

    def to_machine(self, work: list[float]) -> list[float]:
        """Programmed machine coordinates of a work position (G51/G68 are applied later, by stages)."""
        return [w + o for w, o in zip(work, self.offset())]

    def work_position(self, machine: list[float] | None = None) -> list[float]:
        """Work coordinates (mm) of a programmed machine position: the program's own frame."""
        return [m - o for m, o in zip(machine or self.pos, self.offset())]

    # The interpreter's position is the programmed one; the scaling and rotation stages map it to
    # the machine.  These two do the same for what is given in machine coordinates (G53, G28/G30,
    # homing, probing, #5071..): the stages' maps, in the stages' order.
    def machine_frame(self, pose: list[float] | tuple[float, ...]) -> tuple[float, ...]:
        """Where the machine really is for a programmed pose."""
        turn = self.rotation.turn
        if turn is not None:
            pose = rotate_about(pose, self._rotation_pivot(), turn.angle, turn.plane)
        return tuple(self.scaling.scaled(pose))

    def program_frame(self, pose: list[float] | tuple[float, ...]) -> list[float]:
        """The programmed pose that puts the machine at ``pose``."""
        programmed = self.scaling.unscaled(pose)
        turn = self.rotation.turn
        if turn is not None:
            programmed = rotate_about(programmed, self._rotation_pivot(), -turn.angle, turn.plane)
        return list(programmed)

    @contextmanager
    def machine_kept(self) -> Iterator[None]:
        """Switching G51/G68 on, off or to new values never moves the machine: the current point
        is re-expressed from where the machine is, through the new transform (as EdingCNC and
        LinuxCNC derive the current point after any coordinate change)."""
        machine = self.machine_frame(self.pos)
        yield
        self.pos = self.program_frame(machine)

    def _machine_move(self, kind: str, machine: list[float], feed: float = 0.0) -> None:
        """A move to a point given in machine coordinates."""
        self._move(kind, self.program_frame(machine), feed)

    def reported_position(self, machine: list[float] | None = None) -> list[float]:
        """The work position as the controller shows it (#5001.., #5061..): X as a diameter in diameter mode."""
        work = self.work_position(machine)
        if self.diameter_mode:
            work[0] *= 2.0
        return work

    def _live_param(self, index: int) -> float:
        if index >= t.POS_MACHINE:
            return self.machine_frame(self.pos)[index - t.POS_MACHINE]
        if index == t.SPINDLE_SPEED:  # rev/s, following X under constant surface speed
            return self.rpm_at(self.pos[0]) / 60.0 if self.spindle.direction != 5 else 0.0
        return self.reported_position()[index - t.POS_WORK]

    def _axis_values(self, words: Mapping[str, float]) -> dict[int, float]:
        """The axis words of a line, in mm / degrees; in diameter mode X (a diameter) becomes a radius."""
        scale = self.scale
        values = {AXIS_INDEX[a]: v * (scale if a in LINEAR_AXES else 1.0) for a, v in words.items() if a in AXIS_INDEX}
        if 0 in values and self.diameter_mode:
            values[0] /= 2.0
        return values

    def _target(self, words: Mapping[str, float], machine: bool = False,
                start: Sequence[float] | None = None) -> list[float]:
        """Machine position the axis words of a line point at, from ``start`` (default: where the tool is;
        the bulk path passes the end of the batch so far)."""
        axes = self._axis_values(words)
        if machine:  # G53: machine coordinates, absolute
            return self.program_frame([axes.get(i, p) for i, p in enumerate(self.machine_frame(self.pos))])
        target = list(self.pos if start is None else start)
        if self.modal["distance"] == G_91:
            for axis, number in axes.items():
                target[axis] += number
        else:
            offset = self.offset()
            for axis, number in axes.items():
                target[axis] = number + offset[axis]
        return target

    def _select_coord_system(self, code: int) -> None:
        self.modal["coord_system"] = code
        self.params.set(t.COORD_SYSTEM, float(t.COORD_SYSTEM_CODES.index(code) + 1))

    def _rotation(self, code: int, words: Mapping[str, float], span: n.Span) -> None:
        rotation = self.rotation
        with self.machine_kept():
            if code == G_69:
                if rotation.turn is not None:
                    self.canon.event(RotationEvent(self.path, self.line, False))
                rotation.turn = None
                self.params.set(t.G68_ACTIVE, 0.0)
            else:
                turn = rotation.turn = self._turn(words, span)
                values = [1.0, *turn.pivot, 0.0, 0.0, 0.0]
                values[G68_ANGLE_PARAM[turn.plane]] = turn.angle
                for offset, number in enumerate(values):
                    self.params.set(t.G68_ACTIVE + offset, number)
                rotation.sent_pivot = None  # a new G68 reaches the rotation stage once, whether or not
                self._sync_rotation(self.offset())  # offset() (recomputed) has already told it
        self.modal["rotation"] = code

    def _turn(self, words: Mapping[str, float], span: n.Span) -> Turn:
        """G68 X Y Z I J K R (manual 3.6.17): the pivot (work coordinates; the work zero where a word is
        left out), the plane (I1: YZ, J1: XZ, K1: XY, only one; without them the active plane), R."""
        axis_words = [letter for letter in "IJK" if letter in words]
        if len(axis_words) > 1:
            raise self.fail(f"G68 takes one of I1, J1 or K1 (the rotation axis X, Y or Z), not "
                            f"{' and '.join(axis_words)} together", span)
        if axis_words and words[axis_words[0]] != 1:
            raise self.fail(f"G68 {axis_words[0]}{format_value(words[axis_words[0]])}: write "
                            f"{axis_words[0]}1 to turn about {'XYZ'['IJK'.index(axis_words[0])]}", span)
        plane = G68_AXIS_WORDS[axis_words[0]] if axis_words else PLANE_OF[self.modal["plane"]]
        x, y, z = (words.get(letter, 0.0) * self.scale for letter in "XYZ")
        return Turn((x, y, z), words.get("R", 0.0), plane)

    def _rotation_pivot(self) -> tuple[float, ...]:
        """The G68 pivot in programmed machine coordinates (it moves with the work offsets)."""
        assert self.rotation.turn is not None
        off = self.offset()
        return tuple(p + o for p, o in zip(self.rotation.turn.pivot, off))

    def _sync_rotation(self, offset: list[float]) -> None:
        """Tell the rotation stage where the pivot is now (after G68, or when an offset moved it)."""
        rotation = self.rotation
        assert rotation.turn is not None
        pivot = tuple(p + o for p, o in zip(rotation.turn.pivot, offset))
        if pivot != rotation.sent_pivot:
            rotation.sent_pivot = pivot
            self.canon.event(RotationEvent(self.path, self.line, True, pivot, rotation.turn.angle, rotation.turn.plane))

    def _g10(self, code: int, words: Mapping[str, float], span: n.Span) -> None:
        level = int(words.get("L", -1))
        p = words.get("P")
        if level in (1, 10, 11):
            tool = int(p) if p is not None else -1
            if not 1 <= tool <= t.MAX_TOOL:
                raise self.fail(f"G10 L{level} needs a tool number P1..P99", span)
            if level == 1:  # the values as given
                length, x_offset = words.get("Z"), words.get("X")
                length = None if length is None else length * self.scale
                x_offset = None if x_offset is None else x_offset * self.scale
            else:  # from the current position: what makes it read Z (X) in the active system (L10) or G59.3 (L11)
                length, x_offset = self._tool_from_position(level, tool, words)
            if length is not None:
                self.params.set(t.TOOL_LENGTH + tool, length)
            if x_offset is not None and self.config.lathe:
                self.params.set(t.TOOL_X_OFFSET + tool, x_offset)
            if "R" in words:
                self.params.set(t.TOOL_DIAMETER + tool, 2 * words["R"] * self.scale)
            return
        if level not in (2, 20):
            raise self.fail("G10 needs L1, L10 or L11 (tool table), L2 or L20 (coordinate system)", span)
        system = int(p) if p is not None else -1
        if level == 2 and (p is None or p != system or not 1 <= system <= 9):  # manual 3.6.5: P in 1..9
            raise self.fail("G10 L2 needs a coordinate system P1..P9 (P1 = G54 .. P9 = G59.3)", span)
        if p is None or p != system or not 0 <= system <= 9:
            raise self.fail(f"G10 L{level} needs a coordinate system P0..P9 (P1 = G54, P0 = the active one)", span)
        active = int(self.params.read(t.COORD_SYSTEM))
        system = system or active
        axes = self._axis_values(words)
        if level == 20:  # the offset that makes the current point read the words, in system P
            others = [o - self.params.read(t.coord_offset_param(active, i)) for i, o in enumerate(self.offset())]
            base = [self.params.read(t.coord_offset_param(system, i)) + o for i, o in enumerate(others)]
            wanted = self._offset_reading(axes, base)
            axes = {axis: wanted[axis] - others[axis] for axis in sorted(self._solved_axes(axes))}
        for axis, number in axes.items():
            self.params.set(t.coord_offset_param(system, axis), number)

    def _tool_from_position(self, level: int, tool: int,
                            words: Mapping[str, float]) -> tuple[float | None, float | None]:
        """G10 L10/L11: the tool length (and lathe X offset) with which the current position reads the
        programmed Z (X): in the active coordinate system with G92 (L10), or in G59.3 without it (L11).
        G43 adds the tool's wear (zDelta, xDelta) to what is set here, so it is left out of it; in
        diameter mode X is a diameter, as in a move, and the table's X offset a diameter value."""
        offsets = self.offset()
        if level == 10:
            base_x, base_z = offsets[0] - self.offsets.tool_x, offsets[2] - self.offsets.tool_z
        else:
            base_x, base_z = (self.params.read(t.coord_offset_param(9, axis)) for axis in (0, 2))
        wear_x, wear_z = (self.params.read(base + tool) for base in (t.TOOL_X_WEAR, t.TOOL_Z_WEAR))
        wanted = self._axis_values(words)  # X a radius also in diameter mode
        length = self.pos[2] - base_z - wanted[2] - wear_z if 2 in wanted else None
        x_part = 0.5 if self.diameter_mode else 1.0  # G43 applies half the table's X on a diameter lathe
        x_offset = (self.pos[0] - base_x - wanted[0]) / x_part - wear_x if 0 in wanted else None
        return length, x_offset

    def _g28_g30(self, code: int, words: Mapping[str, float], span: n.Span) -> None:
        """Manual 3.6.8: a rapid to the programmed point (if any), then to the stored position of all
        axes (machine coordinates); Z first when that is higher, last otherwise; on a lathe X first."""
        self.refuse_with_comp(t.code_name("G", code), span)
        base = t.G28_HOME if code == G_28 else t.G30_HOME
        if self._axis_values(words):  # the intermediate point, in the current coordinates
            self._move("rapid", self._target(words))
        here = list(self.machine_frame(self.pos))  # the stored positions are machine coordinates
        home = [self.params.read(base + axis) for axis in range(6)]
        if self.config.lathe:  # X first: the tool leaves the part before the carriage travels
            first = 0
        else:
            first = 2 if home[2] > here[2] else -1
        if first >= 0 and here[first] != home[first]:
            here[first] = home[first]
            self._machine_move("rapid", list(here))
        rest = [home[i] if i != 2 or first >= 0 else here[i] for i in range(6)]
        if rest != here:
            here = rest
            self._machine_move("rapid", list(here))
        if here != home:  # Z last, going down
            self._machine_move("rapid", home)

    def _g92(self, code: int, words: Mapping[str, float], span: n.Span) -> None:
        self.refuse_with_comp(t.code_name("G", code), span)
        axes = self._axis_values(words)
        if not axes:
            raise self.fail("G92 needs at least one axis word", span)
        system = int(self.params.read(t.COORD_SYSTEM))
        wanted, solved = self._offset_reading(axes, self.offset()), self._solved_axes(axes)
        values: dict[int, float] = {}
        for axis in range(6):
            tool = self.offsets.tool_z if axis == 2 else self.offsets.tool_x if axis == 0 else 0.0
            g5x = self.params.read(t.coord_offset_param(system, axis))
            if axis in solved:
                values[axis] = wanted[axis] - g5x - tool
            elif not self.offsets.g92_active:
                values[axis] = 0.0
        for axis, number in values.items():
            self.params.set(t.G92_OFFSET + axis, number)
        self.offsets.g92_active = True
        self._offsets_changed()

    def _g92_1(self, code: int, words: Mapping[str, float], span: n.Span) -> None:
        self.refuse_with_comp(t.code_name("G", code), span)
        for axis in range(6):
            self.params.set(t.G92_OFFSET + axis, 0.0)
        self.offsets.g92_active = False
        self._offsets_changed()

    def _g92_2(self, code: int, words: Mapping[str, float], span: n.Span) -> None:
        self.refuse_with_comp(t.code_name("G", code), span)
        self.offsets.g92_active = False
        self._offsets_changed()

    def _g92_3(self, code: int, words: Mapping[str, float], span: n.Span) -> None:
        self.refuse_with_comp(t.code_name("G", code), span)
        self.offsets.g92_active = True
        self._offsets_changed()


# The non-modal G codes this part runs (G4 and G53 belong to other steps).
NON_MODAL: dict[int, Callable[..., None]] = {  # (machine, code, words, span)
    G_10: CoordinateSystems._g10, G_28: CoordinateSystems._g28_g30, G_30: CoordinateSystems._g28_g30,
    G_92: CoordinateSystems._g92, G_92_1: CoordinateSystems._g92_1, G_92_2: CoordinateSystems._g92_2,
    G_92_3: CoordinateSystems._g92_3}
