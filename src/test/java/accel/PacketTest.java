package accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;

import org.junit.jupiter.api.Test;

/** Unit tests for {@link Packet}, the rays of a packet and the packet walk's scratch space. */
class PacketTest {
    /** Test method for {@link Packet#Packet(int)}. */
    @Test
    void testConstructor() {
        // ===== Equivalence Partitions Tests =====
        // TC01: a packet for a stack of 12: empty, room for 12 nodes' first and last rays
        Packet packet = new Packet(12);
        assertEquals(0, packet.size, "TC01: no ray");
        assertEquals(12, packet.firstRays.length, "TC01: first rays");
        assertEquals(12, packet.lastRays.length, "TC01: last rays");
        // ===== Boundary Values Tests =====
        // TC11: no room made for rays before the first
        assertEquals(0, packet.rays.length + packet.leafRays.length, "TC11: no ray made yet");
    }

    /** Test method for {@link Packet#add()}. */
    @Test
    void testAdd() {
        Packet packet = new Packet(4);
        // ===== Equivalence Partitions Tests =====
        // TC01: the first ray: room made for 16, the ray the packet's first
        RayState first = packet.add();
        assertEquals(1, packet.size, "TC01: one ray");
        assertSame(packet.rays[0], first, "TC01: the first ray");
        assertEquals(16, packet.rays.length, "TC01: room for 16 rays");
        assertEquals(16, packet.leafRays.length, "TC01: room for 16 rays at a leaf");
        for (RayState ray : packet.rays)
            assertNotNull(ray, "TC01: every ray made");
        // TC02: an emptied packet hands out the same ray again: no allocation after the first packets
        packet.size = 0;
        assertSame(first, packet.add(), "TC02: the same ray");

        // ===== Boundary Values Tests =====
        // TC11: the 16th ray still fits, the 17th doubles the room, the rays so far kept
        while (packet.size < 16)
            packet.add();
        assertEquals(16, packet.rays.length, "TC11: 16 rays fit");
        RayState seventeenth = packet.add();
        assertEquals(32, packet.rays.length, "TC11: room for 32 rays");
        assertEquals(32, packet.leafRays.length, "TC11: room for 32 rays at a leaf");
        assertSame(first, packet.rays[0], "TC11: the first ray kept");
        assertSame(packet.rays[16], seventeenth, "TC11: the 17th ray");
        assertNotSame(packet.rays[15], seventeenth, "TC11: a ray of its own");
    }
}
