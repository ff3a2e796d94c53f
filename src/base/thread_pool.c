/* collide: the built-in task pool (see thread_pool.h). A task is cut into blocks of at least
 * minRange items; the workers and the finishing thread take blocks with an atomic counter. Which
 * thread runs which block varies; the callers' tasks are written so that the results do not
 * depend on it. Workers look for the next task for a short while before they sleep; the finishing
 * thread waits for the blocks it did not run with a cdSyncCount (a short spin, then asleep until
 * the last block is counted). */
#if defined(__linux__) && !defined(_DEFAULT_SOURCE)
#define _DEFAULT_SOURCE /* syscall (futex) */
#endif
#if !defined(_POSIX_C_SOURCE) || _POSIX_C_SOURCE < 199309L
#undef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 199309L /* clock_gettime */
#endif
#include "thread_pool.h"

#include "collide/collide.h"

#if defined(__EMSCRIPTEN__) || defined(__wasi__) || defined(COLLIDE_NO_THREADS)

cdThreadPool* cdThreadPool_Create(int workerCount)
{
	(void)workerCount;
	return NULL;
}

void cdThreadPool_Destroy(cdThreadPool* pool)
{
	(void)pool;
}

void* cdThreadPool_Enqueue(cdTaskCallback* task, int itemCount, int minRange, void* taskContext, void* pool)
{
	(void)minRange;
	(void)pool;
	task(0, itemCount, 0, taskContext);
	return NULL;
}

void cdThreadPool_Finish(void* userTask, void* pool)
{
	(void)userTask;
	(void)pool;
}

void* cdThreadPool_EnqueueEach(cdTaskCallback* task, int itemCount, void* taskContext, cdThreadPool* pool)
{
	(void)pool;
	task(0, itemCount, 0, taskContext);
	return NULL;
}

void cdThreadPool_Wait(int spin)
{
	(void)spin;
}

#if !defined(__STDC_NO_ATOMICS__)
void cdSyncCount_Init(cdSyncCount* count, int value)
{
	atomic_init(&count->value, value);
	atomic_init(&count->sleepers, 0);
}

void cdSyncCount_Add(cdSyncCount* count, int n)
{
	atomic_fetch_add_explicit(&count->value, n, memory_order_release);
}

void cdSyncCount_AwaitAtLeast(cdSyncCount* count, int target)
{
	while (atomic_load_explicit(&count->value, memory_order_acquire) < target)
	{
	}
}
#endif

#else

#include <pthread.h>
#include <sched.h>
#include <stdatomic.h>
#include <time.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <stdlib.h>
#include <string.h>
#if defined(__linux__)
#include <limits.h>
#include <linux/futex.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

#define CD_POOL_MAX_THREADS 64
#ifndef CD_POOL_BLOCKS_PER_WORKER
#define CD_POOL_BLOCKS_PER_WORKER 16
#endif
/* How long a worker keeps looking for the next task before it sleeps, in nanoseconds. The tasks of
 * one step follow each other within microseconds, while waking a sleeping thread takes tens of
 * microseconds (more in a virtual machine); between steps the workers sleep. */
#define CD_POOL_SPIN_NS 200000

typedef struct cdPoolWorker
{
	cdThreadPool* pool;
	uint32_t index;
} cdPoolWorker;

struct cdThreadPool
{
	pthread_mutex_t mutex;
	pthread_cond_t wake; /* a new task or the end, for the sleeping workers */
	pthread_t threads[CD_POOL_MAX_THREADS];
	cdPoolWorker workers[CD_POOL_MAX_THREADS];
	int threadCount;
	int sleepers; /* workers waiting on wake, under the mutex */
	atomic_bool quit;
	/* The task in progress: its fields are written under the mutex while no thread works on a
	 * task, then generation changes. A worker joins a task under the mutex (active + 1), so the
	 * fields it reads stay as they are until it leaves (active - 1). */
	atomic_uint_fast64_t generation;
	cdTaskCallback* task;
	void* taskContext;
	int itemCount, blockSize, blockCount;
	atomic_int active; /* workers (not the finishing thread) working on the task */
	atomic_int nextBlock;
	cdSyncCount finished; /* blocks finished: each thread adds its count once it finds no more */
};

static void cdPoolPause(void)
{
#if defined(__SSE2__)
	_mm_pause();
#endif
}

static uint64_t cdPoolNow(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (uint64_t)t.tv_sec * 1000000000u + (uint64_t)t.tv_nsec;
}

/* Runs blocks of the current task until none is left, then counts them finished. */
static void cdPoolWork(cdThreadPool* pool, uint32_t workerIndex)
{
	int finished = 0;
	for (;;)
	{
		int block = atomic_fetch_add_explicit(&pool->nextBlock, 1, memory_order_relaxed);
		if (block >= pool->blockCount)
		{
			break;
		}
		int start = block * pool->blockSize;
		int end = start + pool->blockSize < pool->itemCount ? start + pool->blockSize : pool->itemCount;
		pool->task(start, end, workerIndex, pool->taskContext);
		++finished;
	}
	if (finished > 0)
	{
		cdSyncCount_Add(&pool->finished, finished);
	}
}

/* Waits until the generation differs from seen or the pool quits: spinning first, then asleep. */
static void cdPoolAwait(cdThreadPool* pool, uint64_t seen)
{
	uint64_t start = 0;
	for (int spin = 0;; ++spin)
	{
		if (atomic_load_explicit(&pool->generation, memory_order_acquire) != seen ||
			atomic_load_explicit(&pool->quit, memory_order_acquire))
		{
			return;
		}
		cdPoolPause();
		if ((spin & 63) != 63)
		{
			continue;
		}
		uint64_t now = cdPoolNow();
		if (start == 0)
		{
			start = now;
		}
		else if (now - start > CD_POOL_SPIN_NS)
		{
			break;
		}
		/* Now and then let another thread of this core run (a machine with more threads than
		 * cores, the stepping thread among them). */
		sched_yield();
	}
	pthread_mutex_lock(&pool->mutex);
	pool->sleepers++;
	while (atomic_load(&pool->generation) == seen && !atomic_load(&pool->quit))
	{
		pthread_cond_wait(&pool->wake, &pool->mutex);
	}
	pool->sleepers--;
	pthread_mutex_unlock(&pool->mutex);
}

static void* cdPoolThread(void* arg)
{
	cdPoolWorker* worker = (cdPoolWorker*)arg;
	cdThreadPool* pool = worker->pool;
	uint64_t seen = 0;
	for (;;)
	{
		cdPoolAwait(pool, seen);
		pthread_mutex_lock(&pool->mutex);
		if (atomic_load(&pool->quit))
		{
			pthread_mutex_unlock(&pool->mutex);
			break;
		}
		uint64_t generation = atomic_load(&pool->generation);
		if (generation == seen)
		{
			pthread_mutex_unlock(&pool->mutex);
			continue;
		}
		seen = generation;
		atomic_fetch_add(&pool->active, 1);
		pthread_mutex_unlock(&pool->mutex);
		cdPoolWork(pool, worker->index);
		/* Release: the finishing thread reads what the blocks wrote once it sees active at 0. */
		atomic_fetch_sub_explicit(&pool->active, 1, memory_order_release);
	}
	return NULL;
}

cdThreadPool* cdThreadPool_Create(int workerCount)
{
	if (workerCount < 2)
	{
		return NULL;
	}
	cdThreadPool* pool = (cdThreadPool*)cdAlloc(sizeof(cdThreadPool));
	if (pool == NULL)
	{
		return NULL;
	}
	memset(pool, 0, sizeof(*pool));
	if (pthread_mutex_init(&pool->mutex, NULL) != 0)
	{
		cdFree(pool);
		return NULL;
	}
	if (pthread_cond_init(&pool->wake, NULL) != 0)
	{
		pthread_mutex_destroy(&pool->mutex);
		cdFree(pool);
		return NULL;
	}
	atomic_init(&pool->quit, false);
	atomic_init(&pool->generation, 0);
	atomic_init(&pool->active, 0);
	atomic_init(&pool->nextBlock, 0);
	cdSyncCount_Init(&pool->finished, 0);
	int threads = workerCount - 1 < CD_POOL_MAX_THREADS ? workerCount - 1 : CD_POOL_MAX_THREADS;
	for (int i = 0; i < threads; ++i)
	{
		pool->workers[i].pool = pool;
		pool->workers[i].index = (uint32_t)(i + 1);
		if (pthread_create(pool->threads + i, NULL, cdPoolThread, pool->workers + i) != 0)
		{
			break;
		}
		pool->threadCount++;
	}
	if (pool->threadCount == 0)
	{
		cdThreadPool_Destroy(pool);
		return NULL;
	}
	return pool;
}

void cdThreadPool_Destroy(cdThreadPool* pool)
{
	if (pool == NULL)
	{
		return;
	}
	pthread_mutex_lock(&pool->mutex);
	atomic_store(&pool->quit, true);
	pthread_cond_broadcast(&pool->wake);
	pthread_mutex_unlock(&pool->mutex);
	for (int i = 0; i < pool->threadCount; ++i)
	{
		pthread_join(pool->threads[i], NULL);
	}
	pthread_cond_destroy(&pool->wake);
	pthread_mutex_destroy(&pool->mutex);
	cdFree(pool);
}

/* Until no worker works on a task (acquire: what they wrote is seen after). */
static void cdPoolAwaitIdle(cdThreadPool* pool)
{
	for (int spin = 0; atomic_load_explicit(&pool->active, memory_order_acquire) > 0; ++spin)
	{
		cdThreadPool_Wait(spin);
	}
}

/* Publishes the task (blocks of blockSize items) and wakes the sleeping threads. */
static void* cdPoolStart(cdThreadPool* pool, cdTaskCallback* task, int itemCount, int blockSize,
						 void* taskContext)
{
	pthread_mutex_lock(&pool->mutex);
	/* A thread that joined the last task late may still be looking at it (it finds no block). */
	while (atomic_load(&pool->active) > 0)
	{
		pthread_mutex_unlock(&pool->mutex);
		cdPoolAwaitIdle(pool);
		pthread_mutex_lock(&pool->mutex);
	}
	pool->task = task;
	pool->taskContext = taskContext;
	pool->itemCount = itemCount;
	pool->blockSize = blockSize;
	pool->blockCount = (itemCount + blockSize - 1) / blockSize;
	atomic_store_explicit(&pool->nextBlock, 0, memory_order_relaxed);
	atomic_store_explicit(&pool->finished.value, 0, memory_order_relaxed);
	atomic_fetch_add_explicit(&pool->generation, 1, memory_order_release);
	if (pool->sleepers > 0)
	{
		pthread_cond_broadcast(&pool->wake);
	}
	pthread_mutex_unlock(&pool->mutex);
	return pool;
}

void* cdThreadPool_Enqueue(cdTaskCallback* task, int itemCount, int minRange, void* taskContext,
						   void* userContext)
{
	cdThreadPool* pool = (cdThreadPool*)userContext;
	if (itemCount <= 0)
	{
		return NULL;
	}
	int workers = pool->threadCount + 1;
	int blockSize = minRange > 1 ? minRange : 1;
	/* Many blocks per worker (a claim costs one atomic addition), so that a slow thread or a
	 * range of costly items (new contacts among recycled ones) does not hold the others up. */
	int even = (itemCount + CD_POOL_BLOCKS_PER_WORKER * workers - 1) / (CD_POOL_BLOCKS_PER_WORKER * workers);
	if (even > blockSize)
	{
		blockSize = even;
	}
	if (blockSize >= itemCount)
	{
		task(0, itemCount, 0, taskContext);
		return NULL;
	}
	return cdPoolStart(pool, task, itemCount, blockSize, taskContext);
}

void* cdThreadPool_EnqueueEach(cdTaskCallback* task, int itemCount, void* taskContext, cdThreadPool* pool)
{
	if (itemCount <= 0)
	{
		return NULL;
	}
	return cdPoolStart(pool, task, itemCount, 1, taskContext);
}

void cdThreadPool_Wait(int spin)
{
	if (spin < 256)
	{
		for (int i = 0; i < 4; ++i)
		{
			cdPoolPause();
		}
		return;
	}
	sched_yield();
}

void cdThreadPool_Finish(void* userTask, void* userContext)
{
	(void)userContext;
	cdThreadPool* pool = (cdThreadPool*)userTask;
	if (pool == NULL)
	{
		return;
	}
	/* Every block finished (a worker descheduled in the middle of one: this thread sleeps, see
	 * cdSyncCount), then until the workers have left the task (right after they counted their
	 * blocks), so that the next task may change its fields. */
	cdPoolWork(pool, 0);
	cdSyncCount_AwaitAtLeast(&pool->finished, pool->blockCount);
	cdPoolAwaitIdle(pool);
}

/* Turns of a cdSyncCount wait spent pausing before the thread sleeps (a turn is two pauses, 20 to
 * 150 ns each depending on the processor): some tens of microseconds, several blocks' worth. */
#define CD_SYNC_SPINS 512

void cdSyncCount_Init(cdSyncCount* count, int value)
{
	atomic_init(&count->value, value);
	atomic_init(&count->sleepers, 0);
}

void cdSyncCount_Add(cdSyncCount* count, int n)
{
	/* Sequentially consistent, with the sleepers' count below and in the wait: either the waiter
	 * sees the new value, or this sees the waiter and wakes it. */
	atomic_fetch_add(&count->value, n);
#if defined(__linux__)
	if (atomic_load(&count->sleepers) > 0)
	{
		syscall(SYS_futex, (int*)&count->value, FUTEX_WAKE_PRIVATE, INT_MAX, NULL, NULL, 0);
	}
#endif
}

void cdSyncCount_AwaitAtLeast(cdSyncCount* count, int target)
{
	for (int spin = 0; spin < CD_SYNC_SPINS; ++spin)
	{
		if (atomic_load_explicit(&count->value, memory_order_acquire) >= target)
		{
			return;
		}
		cdPoolPause();
		cdPoolPause();
	}
#if defined(__linux__)
	atomic_fetch_add(&count->sleepers, 1);
	for (;;)
	{
		int value = atomic_load(&count->value);
		if (value >= target)
		{
			break;
		}
		/* Sleeps unless the value has changed since it was read (the protocol above misses no
		 * wake-up; the timeout is only a safety net). */
		struct timespec timeout = {0, 1000000};
		syscall(SYS_futex, (int*)&count->value, FUTEX_WAIT_PRIVATE, value, &timeout, NULL, 0);
	}
	atomic_fetch_sub_explicit(&count->sleepers, 1, memory_order_relaxed);
#else
	while (atomic_load_explicit(&count->value, memory_order_acquire) < target)
	{
		sched_yield();
	}
#endif
}

#endif
