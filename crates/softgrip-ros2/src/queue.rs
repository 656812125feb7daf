//! [`DropOldestQueue`]: the bounded queue between the simulation and the publisher thread.
//! A push never waits: when the queue is full the oldest item is dropped and counted.

use std::collections::VecDeque;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Condvar, Mutex, MutexGuard, PoisonError};
use std::time::{Duration, Instant};

/// What [`DropOldestQueue::push`] did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Pushed {
    /// Queued; nothing was dropped.
    Queued,
    /// Queued after dropping the oldest item (the queue was full).
    DroppedOldest,
    /// Not queued: the queue is closed (the item is dropped and counted).
    Closed,
}

/// What [`DropOldestQueue::pop_until`] returned.
#[derive(Debug, PartialEq, Eq)]
pub enum Popped<T> {
    /// The oldest queued item.
    Item(T),
    /// Nothing arrived before the deadline.
    TimedOut,
    /// The queue is closed and empty: no item will come.
    Closed,
}

#[derive(Debug)]
struct State<T> {
    items: VecDeque<T>,
    closed: bool,
}

/// A bounded multi-producer queue that drops its oldest item instead of blocking the producer.
///
/// ```
/// use softgrip_ros2::queue::{DropOldestQueue, Pushed, Popped};
/// let q = DropOldestQueue::new(2);
/// assert_eq!(q.push(1), Pushed::Queued);
/// assert_eq!(q.push(2), Pushed::Queued);
/// assert_eq!(q.push(3), Pushed::DroppedOldest); // 1 is dropped
/// assert_eq!(q.dropped(), 1);
/// assert_eq!(q.try_pop(), Some(2));
/// ```
#[derive(Debug)]
pub struct DropOldestQueue<T> {
    state: Mutex<State<T>>,
    ready: Condvar,
    capacity: usize,
    dropped: AtomicU64,
}

impl<T> DropOldestQueue<T> {
    /// An empty queue holding at most `capacity` items (at least 1).
    pub fn new(capacity: usize) -> Self {
        let capacity = capacity.max(1);
        Self {
            state: Mutex::new(State {
                items: VecDeque::with_capacity(capacity),
                closed: false,
            }),
            ready: Condvar::new(),
            capacity,
            dropped: AtomicU64::new(0),
        }
    }

    // A panic while the lock is held cannot leave the deque inconsistent (every critical
    // section is a single VecDeque call), so a poisoned lock is used as is.
    fn lock(&self) -> MutexGuard<'_, State<T>> {
        self.state.lock().unwrap_or_else(PoisonError::into_inner)
    }

    /// The most items it holds.
    pub fn capacity(&self) -> usize {
        self.capacity
    }

    /// Items queued now.
    pub fn len(&self) -> usize {
        self.lock().items.len()
    }

    /// No item is queued.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Items dropped so far: the oldest ones pushed out by a full queue, and those pushed
    /// after [`close`](Self::close).
    pub fn dropped(&self) -> u64 {
        self.dropped.load(Ordering::Relaxed)
    }

    /// Appends `item`; if the queue is full, drops the oldest item first. Never waits (beyond
    /// the lock, which the consumer holds only to take one item).
    pub fn push(&self, item: T) -> Pushed {
        let mut s = self.lock();
        if s.closed {
            drop(s);
            self.dropped.fetch_add(1, Ordering::Relaxed);
            return Pushed::Closed;
        }
        let full = s.items.len() >= self.capacity;
        let oldest = if full { s.items.pop_front() } else { None };
        s.items.push_back(item);
        drop(s);
        self.ready.notify_one();
        // The dropped item is freed outside the lock.
        drop(oldest);
        if full {
            self.dropped.fetch_add(1, Ordering::Relaxed);
            Pushed::DroppedOldest
        } else {
            Pushed::Queued
        }
    }

    /// Takes the oldest item, if any, without waiting.
    pub fn try_pop(&self) -> Option<T> {
        self.lock().items.pop_front()
    }

    /// Takes the oldest item, waiting until `deadline` for one to arrive.
    pub fn pop_until(&self, deadline: Instant) -> Popped<T> {
        let mut s = self.lock();
        loop {
            if let Some(item) = s.items.pop_front() {
                return Popped::Item(item);
            }
            if s.closed {
                return Popped::Closed;
            }
            let now = Instant::now();
            if now >= deadline {
                return Popped::TimedOut;
            }
            s = self
                .ready
                .wait_timeout(s, deadline - now)
                .unwrap_or_else(PoisonError::into_inner)
                .0;
        }
    }

    /// Takes the oldest item, waiting at most `timeout`.
    pub fn pop_timeout(&self, timeout: Duration) -> Popped<T> {
        self.pop_until(Instant::now() + timeout)
    }

    /// Closes the queue: later pushes are dropped; queued items can still be taken, then
    /// [`Popped::Closed`] is returned.
    pub fn close(&self) {
        self.lock().closed = true;
        self.ready.notify_all();
    }

    /// Removes every queued item and returns how many there were.
    pub fn clear(&self) -> usize {
        let items = std::mem::take(&mut self.lock().items);
        items.len()
    }
}
